"""Symbolic models of the hybrid force/velocity controller and their C emission.

Layers, bottom up (each a module):

- :mod:`codegen.model`: the physics in SymPy (arm, task frames, decoupling law, plant);
- :mod:`codegen.sympy_backend` / :mod:`codegen.casadi_backend`: symbolic outputs to C kernels;
- :mod:`codegen.emit`: the kernels wrapped in the project's one calling convention, as text that is
  the same on every run (the runtime writes it to ``generated/``);
- :mod:`codegen.api`: the public interface, all the runtime calls.

Of ``hybrid``, the generator imports :mod:`hybrid.errors` and :mod:`hybrid.spec` only (plain data it
shares with the runtime): the runtime's fingerprint of the generator hashes exactly those and this folder.
"""
