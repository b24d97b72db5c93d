"""``python -m hybrid generate``: standalone C for a user's arm, their whole controller, or an experiment's
closed loop (its controller and its plant), written into a folder of theirs."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hybrid.errors import HybridError
from hybrid.geometry.part_data import data_file
from hybrid.models.robot import Robot
from hybrid.models.urdf import read_chain
from hybrid.native import cache, generator, units
from hybrid.validate import c_identifier, check_c_name


def generate(urdf, tip: str, out, name: str | None = None, locked: dict | None = None,
             force: bool = False, gravity=(0.0, 0.0, -9.81), constant_model: bool = False) -> list[Path]:
    """Write standalone C99 for the arm of ``urdf`` (``<prefix>.c``, ``.h``, ``.json``) into ``out``.

    ``name`` (:func:`hybrid.validate.c_name_problem`: ASCII letters, digits, single ``_``, a letter first,
    not a C keyword or a system header's name) prefixes the files and symbols; without it a prefix is
    derived from the URDF's robot name. With ``constant_model`` the URDF's parameters are compiled into
    the kernels, which take no ``robot`` array (``<prefix>_constant_parameters`` writes the numbers; the
    manifest records them and their SHA-256). Refuses to overwrite files that differ from what it would
    write unless ``force``.
    """
    if name is not None:
        c_prefix(name, "--name")  # refused before the URDF is read
    parsed = read_chain(urdf, tip, locked)
    prefix = c_prefix(name, "--name", parsed.name)
    robot = Robot(parsed.name, parsed.chain, parsed.links, parsed.damping, gravity, parsed.limits)
    unit = generator.api().build_robot_unit(
        parsed.chain, prefix, units.robot_info(parsed.chain, parsed.name) | {"tip": tip},
        defaults=robot.as_array(), constant=constant_model)
    return write_files(out, unit.files, force)


def c_prefix(name: str | None, what: str, derived_from: str = "") -> str:
    """The prefix of the generated files and symbols: the user's ``name`` (their ``what``) as given or
    refused (:func:`hybrid.validate.check_c_name`), never silently changed; without one, made of
    ``derived_from`` (a robot's name) by :func:`hybrid.validate.c_identifier`."""
    return check_c_name(what, name) if name is not None else c_identifier(derived_from)


def generate_controller(ctrl, out, name: str | None = None, force: bool = False) -> list[Path]:
    """Write the controller ``ctrl`` (a :class:`hybrid.Controller`) as standalone C99 into ``out``:
    ``<prefix>.c``, ``.h`` and ``.json`` (see :meth:`hybrid.Controller.generate`); on a part, its data file
    ``<prefix>_part.bin`` too."""
    prefix = c_prefix(name, "name", f"{ctrl.robot.name}_controller")
    return write_files(out, controller_files(ctrl, prefix) | part_file(ctrl.surface, prefix), force)


def part_file(surface, prefix: str) -> dict[str, bytes]:
    """The data file of the part ``surface`` by its name, ``<prefix>_part.bin`` (none for a formula's surface):
    the numbers the standalone C's ``set_part`` takes (:mod:`hybrid.geometry.part_data`)."""
    return {f"{prefix}_part.bin": data_file(*surface.data())} if surface.local else {}


def controller_files(ctrl, prefix: str, stem: str | None = None) -> dict[str, str]:
    """The standalone C of the controller ``ctrl`` by file name: its symbols start ``prefix``, its files
    ``stem`` (default ``prefix``); generated once per key (cached)."""
    stem = stem or prefix
    path = ctrl.path_references  # a path task's: its table and settings are the generated path's
    follower = None if path is None else path.follower
    variant = ctrl.step_variant()
    values = {k: [float(x) for x in v] for k, v in ctrl.step_inputs(at_start=True).items()}
    values |= {"timing_tolerance": -1.0 if ctrl.timing_tolerance is None else ctrl.timing_tolerance,
               "singular_tol": ctrl.singular_tol}
    spec, axes = variant["spec"], variant["axes"]
    compiled_in = {k: variant[k] for k in ("desired_frame", "position_error", "wrench_sensor")}
    info = {"robot": units.robot_info(variant["chain"], variant["name"]),
            "surface": {"kind": spec.kind, "parameters": list(spec.parameters)}, "axes": list(axes),
            "scheme": ctrl.scheme.name, "step": variant["step"], "variant": compiled_in,
            "task_axes": list(ctrl.axis_names),
            "wrench": ("the force/torque sensor's raw reading, sensor axes about its origin [N, N m] (the sensor "
                       "field's mount, sign, tool, bias and filter turn it into the contact wrench)"
                       if compiled_in["wrench_sensor"] else
                       "the force and moment on the robot at the tip frame's origin, base axes [N, N m]")}
    part = ctrl.surface.local  # a part: the caller gives its grid, each sample expands it about the tip
    if part:
        info["part"] = {"data": f"{prefix}_part.bin", "set": f"{prefix}_controller_set_part",
                        "doc": f"the surface is a part: give {prefix}_controller_set_part the numbers of its data "
                               "file before the first sample (hybrid_part.h's hybrid_part_data checks them)"}
    if follower is not None:
        info["path_task"] = {"axes": list(path.positions), "rows": len(follower.table),
                             "spins": None if path.spins is None else list(path.spins)}
    key = {"chain": units.chain_key(variant["chain"]), "surface": spec.key(), **info, "values": values,
           "generator": generator.fingerprint(), "prefix": prefix, **({"stem": stem} if stem != prefix else {})}
    if follower is not None:
        key["path"] = {"table": cache.digest(follower.table.tobytes()), "settings": follower.settings.tolist()}

    def make() -> dict[str, str]:
        api = generator.api()
        kernels = {k.name: k for k in api.controller_kernels(variant["chain"], spec, axes, **compiled_in)}
        stop = api.safe_stop_kernel(variant["chain"])
        what = (f"the hybrid force/velocity controller ({ctrl.scheme.name} scheme) of the {ctrl.robot.n}-joint arm "
                f"'{variant['name']}' on a {spec.kind}, task axes {', '.join(ctrl.axis_names)}")
        task = None if follower is None else {"measure": kernels["task_measurement"], "axes": path.positions,
                                              "table": follower.table.ravel(), "settings": follower.settings,
                                              "retreat_gains": path.retreat_gains, "spins": path.spins}
        files = api.build_standalone_controller(kernels[variant["step"]], stop, prefix, what, info, values, stem,
                                                task, {"measure": kernels["task_measurement"]} if part else None).files
        if part:  # the part evaluator's header, beside the controller that includes it
            files[api.PART_HEADER] = api.shared_headers()[api.PART_HEADER]
        if follower is not None:  # the follower's header, beside the controller that includes it
            files[api.PATH_HEADER] = api.shared_headers()[api.PATH_HEADER]
        return files

    return cache.generated_unit(stem, key, make)[1]


def generate_experiment(exp, out, name: str | None = None, force: bool = False) -> list[Path]:
    """Write the closed loop of the experiment ``exp`` as standalone C99 into ``out``: its controller
    (``<name>_controller.c``, ``.h``, ``.json``: the struct ``<name>_controller``, as
    :meth:`hybrid.Controller.generate` writes it, symbols ``<name>_...``) and its plant
    (``<name>_plant.c``, ``.h``, ``.json``: the struct ``<name>_plant`` with the experiment's parameters,
    timing and start state; :func:`hybrid.codegen.api.build_standalone_plant`); on a part, the evaluator's
    header ``hybrid_part.h`` and the part's data file ``<name>_part.bin``, which both take at run time
    (``<name>_controller_set_part``, ``<name>_plant_set_part``). ``name`` defaults to the robot's.
    Files in ``out`` with other content are refused unless ``force``."""
    prefix = c_prefix(name, "name", exp.robot.name)
    if not exp.sensor.ideal or exp.wrench_sensor is not None:
        raise HybridError("the standalone plant gives its sensor's force as the reading: an experiment with a "
                          "sensor signal (noise, bias, lag, delay) or a wrench_sensor runs in Python only; leave them "
                          "out to generate it")
    if exp.controller_surface is not None and (exp.surface.local or exp.controller_surface.local):
        raise HybridError("the standalone C takes one part, the controller's and the plant's: an experiment whose "
                          "controller is told a surface other than the plant's, either of them a part, runs in Python "
                          "only; leave controller_surface out to generate it")
    ctrl = exp.build_controller()
    x0 = exp.checked_start()  # the run the C makes: refused where simulate refuses it
    data = part_file(exp.surface, prefix)
    files = controller_files(ctrl, prefix, f"{prefix}_controller") | plant_files(exp, f"{prefix}_plant", x0, data)
    return write_files(out, files | data, force)


def plant_files(exp, prefix: str, x0, data: dict[str, bytes] | None = None) -> dict[str, str]:
    """The standalone C of the plant of ``exp`` (starting from ``x0``) by file name; generated once per
    key (cached). On a part, ``data`` is its data file by name (:func:`part_file`), and the manifest gives
    the part by the file's name and SHA-256 (not the mesh the experiment's settings hold)."""
    plant = exp.plant_class.loop_plant(exp)
    part = exp.surface.local  # its surface is the part's expansion about the sensor tip, each step's
    inputs = exp.plant_class.inputs(exp)
    values = {k: [float(v) for v in np.asarray(a, float).ravel()] for k, a in inputs.items()
              if not (part and k == "surface")}
    values |= {"x0": [float(v) for v in x0], "h": float(exp.integration_step),
               "steps_per_sample": int(exp.steps_per_sample), "sample_time": float(exp.sample_time),
               "duration": float(exp.duration),
               # the metrics' references: hybrid.metrics takes the experiment's steps (a path task's force at its
               # start and speed 0, not the follower's references the controller adds to its steps)
               "references": [float(v) for step in (exp.force_reference, exp.speed_reference)
                              for v in (step.before, step.after, step.at)]}
    robot, surface = exp.robot, (exp.section or exp.surface).kind
    settings = exp.to_dict()
    if part:
        (file, content), = (data or part_file(exp.surface, prefix)).items()
        settings["surface"] = {"kind": surface, "data": file, "spacing": exp.surface.fit.spacing_m,
                               "band": exp.surface.fit.band_m, "data_sha256": cache.digest(content)}
    info = {"robot": {"robot": robot.name, "joints": list(robot.joint_names)}, "surface": surface,
            "plant": plant.key()[0], "experiment": settings}
    if part:
        info["part"] = {"data": file, "set": f"{prefix}_set_part",
                        "doc": f"the surface is a part: give {prefix}_set_part the numbers of its data file before "
                               "the first step; the contact acts on its expansion about the sensor tip, taken at "
                               "the start of each RK4 step"}
    backend = robot.kind.plant_printer(exp.backend)
    key = {"plant": plant.key(), "values": values, "info": info, "backend": backend,
           "generator": generator.fingerprint(), "prefix": prefix}

    def make() -> dict[str, str]:
        api = generator.api()
        rhs, outputs, force = plant.kernels(api)
        what = (f"the plant of an experiment: the {robot.n}-joint arm '{robot.name}', its force sensor and penalty "
                f"contact with friction on a {surface}, advanced by RK4 with the torque held")
        files = api.build_standalone_plant(rhs, outputs, force, prefix, what, info, values, backend, part,
                                           exp.path_task is not None).files
        if part:  # the part evaluator's header, beside the plant that includes it
            files[api.PART_HEADER] = api.shared_headers()[api.PART_HEADER]
        return files

    return cache.generated_unit(prefix, key, make)[1]


def write_files(out, files: dict[str, str | bytes], force: bool) -> list[Path]:
    """``files`` (texts or bytes) written into the folder ``out``, each atomically; files there with other
    content are refused unless ``force``."""
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise HybridError(f"--out {out} is a file; give a folder")
    files = {n: data if isinstance(data, bytes) else data.encode() for n, data in files.items()}
    clash = [n for n, data in files.items() if (out / n).is_file() and (out / n).read_bytes() != data]
    if clash and not force:
        raise HybridError(f"{', '.join(clash)} already exist in {out} with other content; "
                          "pass --force to overwrite them, or choose another --out or --name")
    try:
        cache.write_unit_files(out, files)
    except OSError as exc:
        raise HybridError(f"cannot write into {out} ({exc.strerror}); choose a writable --out") from None
    return [out / n for n in files]
