"""Symbolic models of the hybrid force/velocity controller and their C emission.

Layers, bottom up (each a module):

- :mod:`codegen.model`: the physics in SymPy (arm, task frames, decoupling law, plant);
- :mod:`codegen.sympy_backend` / :mod:`codegen.casadi_backend`: symbolic outputs to C kernels;
- :mod:`codegen.emit`: the kernels wrapped in the project's one calling convention, written to
  ``generated/`` deterministically.
"""
