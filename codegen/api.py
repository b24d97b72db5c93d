"""The generator's public interface: everything the runtime asks of it, each under one name.

The runtime reaches the generator through :mod:`hybrid.native.generator` alone, which imports this
module when a unit must be generated. Its functions take plain descriptions (a
:class:`hybrid.spec.chain.Chain`, a :class:`hybrid.spec.surface.SurfaceSpec`, task-axis indices,
names, flags and numbers) or kernels they returned, and give kernels or generated units (a
:class:`Unit`: C source, header and manifest as text); none reads or writes a file.

- the paper's planar arm in closed form: :func:`planar_kernels`, :func:`build_planar_unit` (one
  backend of ``BACKENDS``: the committed ``generated/hybrid_<backend>.*``);
- any serial chain: :func:`build_robot_unit` (terms, dynamics, operational space; :func:`robot_kernels`,
  and with the parameters compiled in, :func:`constant_kernels`), :func:`build_inertia_unit` (the inertia
  ``B(q)`` alone),
  :func:`build_regressor_unit` (the joint-torque regressor ``tau = Y pi``),
  :func:`law_kernels` / :func:`build_law_unit` (the decoupling law on a surface),
  :func:`build_frame_unit` (the task frame), :func:`controller_kernels` /
  :func:`build_controller_unit` (one control sample, and :func:`safe_stop_kernel`: its fault
  reaction's torque), :func:`plant_kernels` /
  :func:`build_plant_unit` (the 3-D plant);
- a closed loop of a plant's kernels and a controller step: :class:`LoopSpec`,
  :func:`build_closed_loop_unit`;
- standalone C for a user's project: :func:`build_standalone_controller`, :func:`build_standalone_plant`;
- the headers the units include: :func:`shared_headers` (the path follower's: :func:`path_header`); the
  environment that renders C templates
  (:func:`template_environment`, for another C program of the project's);
- a surface's ``phi`` in CasADi (:func:`phi_sx`) and a kernel as a CasADi Function
  (:func:`kernel_function`);
- what a closed loop's lanes execute: :func:`loop_census` (its vector operations by kind per RK4 step, and
  its chain; :func:`kernel_census` for one kernel, ``CENSUS_KINDS`` the kinds).
"""

from __future__ import annotations

from hybrid.spec.stamp import stamp

from .casadi_backend import kernel_function
from .census import KINDS as CENSUS_KINDS
from .census import kernel_census, loop_census
from .closed_loop import LoopSpec, build_closed_loop_unit
from .constant_model import constant_kernels
from .controller_step import controller_kernels
from .emit import BACKENDS, Unit
from .emit import build_unit as build_planar_unit
from .lanes import LANES_HEADER, lanes_header
from .model import kernels as planar_kernels
from .part_grid import PART_HEADER, part_header
from .path_follow import PATH_HEADER, path_header
from .regressor import build_regressor_unit
from .robot_unit import (
    build_controller_unit,
    build_frame_unit,
    build_inertia_unit,
    build_law_unit,
    build_plant_unit,
    build_robot_unit,
    robot_kernels,
)
from .safe_stop import safe_stop_kernel
from .spatial_plant import plant_kernels
from .standalone_controller import build_standalone_controller
from .standalone_plant import build_standalone_plant
from .surfaces import phi_sx
from .task_law import law_kernels
from .templates import environment_for as template_environment


def shared_headers() -> dict[str, str]:
    """The headers the units include (the SIMD lanes', :data:`LANES_HEADER`; the path follower's,
    :data:`PATH_HEADER`), by file name, stamped as generated files: one copy beside the units in
    ``generated/``."""
    return {LANES_HEADER: stamp(lanes_header()), PATH_HEADER: stamp(path_header()), PART_HEADER: stamp(part_header())}


__all__ = ["BACKENDS", "CENSUS_KINDS", "LANES_HEADER", "PART_HEADER", "PATH_HEADER", "LoopSpec", "Unit",
           "build_closed_loop_unit", "build_controller_unit", "build_frame_unit", "build_inertia_unit",
           "build_law_unit", "build_planar_unit", "build_plant_unit", "build_regressor_unit", "build_robot_unit",
           "build_standalone_controller", "build_standalone_plant", "constant_kernels", "controller_kernels",
           "kernel_census", "kernel_function", "law_kernels", "loop_census", "path_header", "phi_sx",
           "planar_kernels", "plant_kernels", "robot_kernels", "safe_stop_kernel", "shared_headers",
           "template_environment"]
