"""Every compiled unit the runtime uses, each built once and cached: the one door to the generator.

The committed units (:func:`planar_unit`, the paper's arm in closed form) are compiled from
``generated/``. A robot's units (its terms, its law on a surface, its controller step, its plant,
a closed loop) are generated for its kinematic structure when first asked for, then compiled:
both steps are cached on disk by a key over what they are built from, the generator's own
source and the versions of SymPy and CasADi (:mod:`hybrid.native.build`). The code generator
(:mod:`hybrid.codegen`, SymPy and CasADi) is imported here only, and only when a unit must be
generated, so the runtime starts without it.
"""

from __future__ import annotations

import dataclasses
import importlib
import json
from functools import cache
from importlib.metadata import version

from hybrid.errors import HybridError
from hybrid.native import build
from hybrid.native.binding import Unit
from hybrid.validate import c_identifier

#: what a singular planar pose means, added to SingularConfigurationError messages
PLANAR_SINGULAR = " (elbow q2 near 0 or pi)"
#: the committed units, by backend
BACKENDS = ("sympy", "casadi")


def generator(module: str):
    """The generator's module ``hybrid.codegen.<module>``, imported on first use (it loads SymPy and
    CasADi: a runtime that finds every unit in its cache never needs it)."""
    return importlib.import_module(f"hybrid.codegen.{module}")


def planar_unit(backend: str) -> Unit:
    """The committed planar unit of ``backend``, bound from its manifest."""
    if not isinstance(backend, str) or backend not in BACKENDS:
        raise HybridError(f"backend must be 'sympy' or 'casadi', got {backend!r:.40}")
    return _planar_unit(backend)


@cache
def _planar_unit(backend: str) -> Unit:
    return Unit(build.load(backend), build.manifest(backend), PLANAR_SINGULAR, {"qd": "qdot", "rd": "rdot"},
                folder=build.source_dir())


def chain_key(chain) -> str:
    """The kinematic structure as stable text (a cache key)."""
    return json.dumps(dataclasses.asdict(chain), sort_keys=True)


def robot_info(chain, name: str) -> dict:
    """What a robot's manifests say of it: its name and joints."""
    return {"robot": name, "joints": [{"name": j.name, "type": j.kind} for j in chain.joints]}


def compiled(prefix: str, key: dict, make) -> Unit:
    """Generate (cached by ``key``, the generator's source and the versions of SymPy and CasADi),
    compile (cached) and load the unit that ``make()`` builds."""
    key = {**key, "generator": generator("emit").fingerprint(), "casadi": version("casadi"),
           "sympy": version("sympy"), "prefix": prefix}
    folder = build.generated_unit(prefix, key, lambda: make().files)
    module, manifest = build.load_generated(folder, prefix)
    return Unit(module, manifest, " (a wrist, elbow or shoulder singularity)",
                {"qd": "qdot", "pd": "pdot"}, folder=folder)


@cache
def robot_unit(chain, name: str) -> Unit:
    """The rigid-body kernels of ``chain`` (terms, dynamics, operational space), compiled."""
    prefix = c_identifier(f"hybrid_{name}")
    return compiled(prefix, {"chain": chain_key(chain)},
                    lambda: generator("robot_unit").build_robot_unit(chain, prefix, robot_info(chain, name)))


@cache
def law_unit(chain, name: str, spec, axes: tuple[int, ...]) -> Unit:
    """The task frame and decoupling law of ``chain`` on the surface ``spec``, compiled."""
    prefix = c_identifier(f"hybrid_{name}_{spec.kind}_law")
    return compiled(prefix, {"chain": chain_key(chain), "surface": spec.key(), "axes": list(axes)},
                    lambda: generator("robot_unit").build_law_unit(chain, spec, axes, prefix,
                                                                    robot_info(chain, name)))


@cache
def frame_unit(spec) -> Unit:
    """The task frame on the surface ``spec`` (any robot's), compiled."""
    prefix = c_identifier(f"hybrid_{spec.kind}_frame")
    return compiled(prefix, {"surface": spec.key()},
                    lambda: generator("robot_unit").build_frame_unit(spec, prefix))


@cache
def controller_unit(chain, name: str, spec, axes: tuple[int, ...], desired_frame: bool = False,
                    position_error: bool = False) -> Unit:
    """One control sample (measurement, loops, law) of ``chain`` on the surface ``spec``, compiled;
    the loop frame at the desired point and the position-error loops are compiled-in variants."""
    variant = {"desired_frame": desired_frame, "position_error": position_error}
    suffix = "".join(f"_{k}" for k, on in variant.items() if on)
    prefix = c_identifier(f"hybrid_{name}_{spec.kind}_controller{suffix}")
    return compiled(prefix, {"chain": chain_key(chain), "surface": spec.key(), "axes": list(axes), **variant},
                    lambda: generator("robot_unit").build_controller_unit(chain, spec, axes, prefix,
                                                                           robot_info(chain, name), variant))


@cache
def plant_unit(chain, name: str, spec) -> Unit:
    """The 3-D experiment's plant of ``chain`` in contact with the surface ``spec``, compiled."""
    prefix = c_identifier(f"hybrid_{name}_{spec.kind}_plant")
    return compiled(prefix, {"chain": chain_key(chain), "surface": spec.key(), "plant": 1},
                    lambda: generator("robot_unit").build_plant_unit(chain, spec, prefix, robot_info(chain, name)))


def loop_unit(plant: tuple, variant: dict, lanes: int | None) -> Unit:
    """The whole closed loop of a plant (``("planar", surface kind)`` or ``("spatial", chain, name,
    surface spec)``) and a controller step (``variant``: its chain, name, surface spec, axes, variants
    and step function); ``lanes=1``: the build for one run at a time."""
    v = variant
    kind = plant[1] if plant[0] == "planar" else f"{plant[2]}_{plant[3].kind}"
    prefix = c_identifier(f"hybrid_{v['name']}_{kind}_{v['step']}_loop{'_one' if lanes == 1 else ''}")
    plant_key = list(plant) if plant[0] == "planar" else ["spatial", chain_key(plant[1]), plant[3].key()]
    key = {"chain": chain_key(v["chain"]), "surface": v["spec"].key(), "axes": list(v["axes"]), "plant": plant_key,
           **{k: v[k] for k in ("desired_frame", "position_error", "step")}, "lanes": lanes}
    return compiled(prefix, key, lambda: _build_loop(prefix, plant, v, lanes))


def _build_loop(prefix: str, plant: tuple, v: dict, lanes: int | None):
    steps = {k.name: k for k in generator("controller_step").controller_kernels(
        v["chain"], v["spec"], v["axes"], v["desired_frame"], v["position_error"])}
    if plant[0] == "planar":
        kernels = {k.name: k for k in generator("model").kernels(2)}
        rhs, outputs, force = kernels[f"plant_rhs_{plant[1]}"], kernels[f"plant_outputs_{plant[1]}"], ("Fc_x", "Fc_y")
        what = f"the paper's closed loop on a {plant[1]}"
    else:
        kernels = {k.name: k for k in generator("spatial_plant").plant_kernels(plant[1], plant[3])}
        rhs, outputs, force = kernels["plant_rhs"], kernels["plant_outputs"], ("Fc_x", "Fc_y", "Fc_z")
        what = f"the 3-D experiment's closed loop: {plant[2]} on a {plant[3].kind}"
    info = {"plant": plant[0], "surface": plant[1] if plant[0] == "planar" else plant[3].kind, "step": v["step"],
            "robot": v["name"]}
    loop = generator("closed_loop")
    return loop.build_closed_loop_unit(loop.LoopSpec(rhs, outputs, steps[v["step"]], force), prefix,
                                       f"{what}: {v['step']}", info, lanes)
