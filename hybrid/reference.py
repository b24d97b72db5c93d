"""Deprecated: the NumPy oracle is :mod:`hybrid.oracle`; this name is removed in the next release.

``from hybrid import reference`` gives :mod:`hybrid.oracle` itself, with a ``DeprecationWarning``.
"Reference" in this library names a signal (the force and speed references ``F_d(t)``, ``v_d(t)``).
"""

import sys
import warnings

from hybrid import oracle

warnings.warn("hybrid.reference is renamed hybrid.oracle (the NumPy oracle); import hybrid.oracle",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = oracle
