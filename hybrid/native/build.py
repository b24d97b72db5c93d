"""The native build in one name: compiling (:mod:`hybrid.native.compiler`), caching
(:mod:`hybrid.native.cache`) and loading (:mod:`hybrid.native.loader`) the generated C.

The units (:mod:`hybrid.native.units`), the closed loop and the planar plant reach the build
through this module; everything else imports from the module a name lives in.
"""

from __future__ import annotations

from hybrid.native.cache import generated_unit
from hybrid.native.compiler import ready_for_threads
from hybrid.native.loader import load, load_generated, manifest, read_manifest, source_dir, warn_if_hand_edited

__all__ = ["generated_unit", "load", "load_generated", "manifest", "read_manifest", "ready_for_threads",
           "source_dir", "warn_if_hand_edited"]
