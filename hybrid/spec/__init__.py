"""What the code generator and the runtime share, as plain data: the interfaces between generated C
and Python (:mod:`hybrid.spec.interfaces`) and the descriptions the generator compiles.

Nothing here computes beyond checking its own data; ``hybrid.codegen`` imports nothing of the runtime
but this package and :mod:`hybrid.errors`.
"""
