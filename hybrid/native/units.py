"""Every compiled unit the runtime uses, each built once and cached.

The committed units (:func:`planar_unit`, the paper's arm in closed form) are compiled from
``generated/``. A robot's units (its terms, with its parameters compiled in or not, its law on a
surface, its controller step, its plant, a closed loop) are generated for its kinematic structure
when first asked for, then compiled: both steps are cached on disk by a key over what they are
built from, the generator's fingerprint and the versions of SymPy and CasADi
(:mod:`hybrid.native.cache`). The code generator is reached through :mod:`hybrid.native.generator`,
only when a unit must be generated, so the runtime starts without it.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
from functools import cache
from pathlib import Path

from hybrid.errors import HybridError, NativeBuildError
from hybrid.native import generator, loader
from hybrid.native.binding import Unit
from hybrid.native.cache import generated_unit
from hybrid.spec import chain as rb
from hybrid.spec import stamp
from hybrid.spec.interfaces import PRINTERS
from hybrid.validate import c_identifier, shown

#: what a singular planar pose means, added to SingularConfigurationError messages
PLANAR_SINGULAR = " (elbow q2 near 0 or pi)"
#: the committed units, by backend
BACKENDS = PRINTERS


def planar_unit(backend: str) -> Unit:
    """The committed planar unit of ``backend``, bound from its manifest."""
    if not isinstance(backend, str) or backend not in BACKENDS:
        raise HybridError(f"backend must be 'sympy' or 'casadi', got {shown(backend, 40)}")
    return _planar_unit(backend)


@cache
def _planar_unit(backend: str) -> Unit:
    return Unit(lambda: loader.load(backend), loader.manifest(backend), PLANAR_SINGULAR, {"qd": "qdot", "rd": "rdot"},
                folder=loader.source_dir())


def chain_key(chain) -> str:
    """The kinematic structure as stable text (a cache key)."""
    return json.dumps(dataclasses.asdict(chain), sort_keys=True)


def robot_info(chain, name: str) -> dict:
    """What a robot's manifests say of it: its name and joints."""
    return {"robot": name, "joints": [{"name": j.name, "type": j.kind} for j in chain.joints]}


@cache
def _tool_versions() -> dict:
    """The generator's tools' versions (read from their installed metadata, not by importing them)."""
    import importlib.metadata  # slow to import (it parses e-mail headers): only when a unit is asked for

    return {tool: importlib.metadata.version(tool) for tool in ("casadi", "sympy")}


#: the folder of ``generated/`` holding the committed closed loops, and its index of them
LOOPS, LOOP_INDEX = "loops", "index.json"


def committed_key(prefix: str, key: dict) -> str:
    """The digest a committed unit is filed under: ``key`` and the generator's fingerprint (not the
    tools' versions: C the pinned tools wrote is as good as C from others)."""
    material = json.dumps({**key, "generator": generator.fingerprint(), "prefix": prefix}, sort_keys=True)
    return hashlib.sha256(material.encode()).hexdigest()


def _committed_folder(prefix: str, key: dict) -> Path | None:
    """``generated/loops`` when it holds the unit ``prefix`` for this very ``key``, else None."""
    try:
        folder = loader.source_dir() / LOOPS
        index = json.loads((folder / LOOP_INDEX).read_text())["loops"]
    except (NativeBuildError, OSError, ValueError, KeyError, TypeError):  # none committed here: generate it
        return None
    if not isinstance(index, dict) or index.get(prefix) != committed_key(prefix, key):
        return None
    # a unit whose files are not all there is generated instead
    return folder if all((folder / f"{prefix}{ext}").is_file() for ext in (".c", ".h", ".json")) else None


def compiled(prefix: str, key: dict, make) -> Unit:
    """The unit that ``make()`` builds: committed in ``generated/`` for this key, else generated
    (cached by ``key``, the generator's fingerprint and the versions of SymPy and CasADi); it is
    compiled (cached) and loaded when first used."""
    committed = _committed_folder(prefix, key)
    # a cached unit's files are read once, verified against their checksums, and compiled as read
    folder, texts = (committed, None) if committed else generated_unit(
        prefix, {**key, "generator": generator.fingerprint(), **_tool_versions(), "prefix": prefix},
        lambda: make().files)

    def load():
        if committed:  # C in generated/ a user may have edited: said, and used as it is
            loader.warn_if_hand_edited(folder, {n: (folder / n).read_text() for n in (f"{prefix}.c", f"{prefix}.h")})
        return loader.load_generated(folder, prefix, texts)

    return Unit(load, loader.read_manifest(folder, prefix, texts),
                " (a wrist, elbow or shoulder singularity)",
                {"qd": "qdot", "pd": "pdot"}, folder=folder)


@cache
def robot_unit(chain, name: str) -> Unit:
    """The rigid-body kernels of ``chain`` (terms, dynamics, operational space), compiled."""
    prefix = c_identifier(f"hybrid_{name}")
    return compiled(prefix, {"chain": chain_key(chain)},
                    lambda: generator.api().build_robot_unit(chain, prefix, robot_info(chain, name)))


def constant_key(chain, values) -> dict:
    """What a constant model of ``chain`` with the ``robot`` array ``values`` is cached by: the structure
    and the numbers exactly (:func:`hybrid.spec.chain.exact_values`: one ulp apart are two models)."""
    return _exact_key(chain, rb.exact_values(values))


def _exact_key(chain, exact: tuple[str, ...]) -> dict:
    return {"chain": chain_key(chain), "constant": list(exact)}


def constant_robot_unit(chain, name: str, values) -> Unit:
    """The rigid-body kernels of ``chain`` with the ``robot`` array ``values`` compiled in (a constant
    model: the kernels take no ``robot`` array), compiled; cached by :func:`constant_key`."""
    return _constant_robot_unit(chain, name, rb.exact_values(values))


@cache
def _constant_robot_unit(chain, name: str, exact: tuple[str, ...]) -> Unit:
    prefix = c_identifier(f"hybrid_{name}_constant")
    values = [float.fromhex(v) for v in exact]
    return compiled(prefix, _exact_key(chain, exact),
                    lambda: generator.api().build_robot_unit(chain, prefix, robot_info(chain, name), values,
                                                             constant=True))


@cache
def inertia_unit(chain, name: str) -> Unit:
    """The joint-space inertia ``B(q)`` of ``chain`` alone (the CRBA of :func:`robot_unit`'s terms), compiled."""
    prefix = c_identifier(f"hybrid_{name}_crba")
    return compiled(prefix, {"chain": chain_key(chain), "inertia": 1},
                    lambda: generator.api().build_inertia_unit(chain, prefix, robot_info(chain, name)))


def constant_inertia_unit(chain, name: str, values) -> Unit:
    """:func:`inertia_unit` with the ``robot`` array ``values`` compiled in (a constant model), compiled;
    cached by :func:`constant_key`."""
    return _constant_inertia_unit(chain, name, rb.exact_values(values))


@cache
def _constant_inertia_unit(chain, name: str, exact: tuple[str, ...]) -> Unit:
    prefix = c_identifier(f"hybrid_{name}_constant_crba")
    values = [float.fromhex(v) for v in exact]
    return compiled(prefix, {**_exact_key(chain, exact), "inertia": 1},
                    lambda: generator.api().build_inertia_unit(chain, prefix, robot_info(chain, name), values))


@cache
def regressor_unit(chain, name: str) -> Unit:
    """The joint-torque regressor of ``chain`` (``tau = Y pi``), compiled."""
    prefix = c_identifier(f"hybrid_{name}_regressor")
    return compiled(prefix, {"chain": chain_key(chain), "regressor": 1},
                    lambda: generator.api().build_regressor_unit(chain, prefix, robot_info(chain, name)))


@cache
def law_unit(chain, name: str, spec, axes: tuple[int, ...]) -> Unit:
    """The task frame and decoupling law of ``chain`` on the surface ``spec``, compiled."""
    prefix = c_identifier(f"hybrid_{name}_{spec.kind}_law")
    return compiled(prefix, {"chain": chain_key(chain), "surface": spec.key(), "axes": list(axes)},
                    lambda: generator.api().build_law_unit(chain, spec, axes, prefix,
                                                              robot_info(chain, name)))


@cache
def frame_unit(spec) -> Unit:
    """The task frame on the surface ``spec`` (any robot's), compiled."""
    prefix = c_identifier(f"hybrid_{spec.kind}_frame")
    return compiled(prefix, {"surface": spec.key()},
                    lambda: generator.api().build_frame_unit(spec, prefix))


@cache
def controller_unit(chain, name: str, spec, axes: tuple[int, ...], desired_frame: bool = False,
                    position_error: bool = False, wrench_sensor: bool = False) -> Unit:
    """One control sample (measurement, loops, law) of ``chain`` on the surface ``spec``, compiled;
    the loop frame at the desired point, the position-error loops and a force/torque sensor's reading
    are compiled-in variants."""
    variant = {"desired_frame": desired_frame, "position_error": position_error, "wrench_sensor": wrench_sensor}
    suffix = "".join(f"_{k}" for k, on in variant.items() if on)
    prefix = c_identifier(f"hybrid_{name}_{spec.kind}_controller{suffix}")
    return compiled(prefix, {"chain": chain_key(chain), "surface": spec.key(), "axes": list(axes), **variant},
                    lambda: generator.api().build_controller_unit(chain, spec, axes, prefix,
                                                                     robot_info(chain, name), variant))


@cache
def plant_unit(chain, name: str, spec) -> Unit:
    """The 3-D experiment's plant of ``chain`` in contact with the surface ``spec``, compiled."""
    prefix = c_identifier(f"hybrid_{name}_{spec.kind}_plant")
    return compiled(prefix, {"chain": chain_key(chain), "surface": spec.key(), "plant": 1},
                    lambda: generator.api().build_plant_unit(chain, spec, prefix, robot_info(chain, name)))


def loop_unit(plant, variant: dict, lanes: int | None) -> Unit:
    """The whole closed loop of a generated plant (a :class:`hybrid.plants.interface.LoopPlant`) and a
    controller step (``variant``: its chain, name, surface spec, axes, variants and step function);
    ``lanes=1``: the build for one run at a time."""
    prefix, key = _loop_key(plant, variant, lanes)
    return compiled(prefix, key, lambda: _build_loop(prefix, plant, variant, lanes))


def _loop_key(plant, v: dict, lanes: int | None) -> tuple[str, dict]:
    path, part = v.get("path_task", False), v.get("part", False)
    prefix = c_identifier(f"hybrid_{v['name']}_{plant.name}_{v['step']}{'_path' if path else ''}"
                          f"{'_part' if part else ''}_loop{'_one' if lanes == 1 else ''}")
    key = {"chain": chain_key(v["chain"]), "surface": v["spec"].key(), "axes": list(v["axes"]), "plant": plant.key(),
           **{k: v[k] for k in ("desired_frame", "position_error", "wrench_sensor", "step")}, "lanes": lanes,
           **({"path_task": True} if path else {}), **({"part": True} if part else {})}
    return prefix, key


def loop_files(loops) -> dict[str, str]:
    """The files of ``generated/loops`` for the closed loops ``loops`` (``(plant, variant, lanes)`` each):
    each unit's C, header and manifest, and the index that files each under its key."""
    files, index = {}, {}
    for plant, variant, lanes in loops:
        prefix, key = _loop_key(plant, variant, lanes)
        files.update(_build_loop(prefix, plant, variant, lanes).files)
        index[prefix] = committed_key(prefix, key)
    data = {"do_not_edit": stamp.MANIFEST_STAMP, "loops": index}
    files[LOOP_INDEX] = json.dumps({**data, "body_sha256": stamp.json_body_hash(data)}, indent=1) + "\n"
    return files


def loop_spec(plant, variant: dict):
    """What the closed loop of ``plant`` and the controller step ``variant`` (as :func:`loop_unit`'s) is
    made of: a :class:`hybrid.codegen.api.LoopSpec` (the plant's kernels, the step's kernel; with
    ``path_task`` true in ``variant``, the controller's measurement for the path's follower; with ``part`` true,
    for the part's expansion)."""
    v, api = variant, generator.api()
    steps = {k.name: k for k in api.controller_kernels(
        v["chain"], v["spec"], v["axes"], v["desired_frame"], v["position_error"], v["wrench_sensor"])}
    rhs, outputs, force = plant.kernels(api)
    path, part = v.get("path_task", False), v.get("part", False)
    return api.LoopSpec(rhs, outputs, steps[v["step"]], force, api.safe_stop_kernel(v["chain"]),
                        steps["task_measurement"] if path or part else None, tuple(v["axes"]) if path else None,
                        part)


def _build_loop(prefix: str, plant, v: dict, lanes: int | None):
    info = {"plant": plant.key()[0], "surface": plant.name, "step": v["step"], "robot": v["name"]}
    return generator.api().build_closed_loop_unit(loop_spec(plant, v), prefix, f"{plant.what}: {v['step']}", info,
                                                  lanes)
