"""The closed loop on a part in C alone (``Experiment.generate``) is ``hybrid.simulate``'s run, and the part's
data file the C reads at run time is checked by the C before it is used.

An experiment on a part is generated (the controller, the plant, ``hybrid_part.h`` and the part's data file
``ur5_part.bin``), built with examples/closed_loop_c's ``main.c`` and ``-std=c99 -Wall -Wextra -Werror
-pedantic``, and run; it reads the data file and gives its numbers to the controller and the plant. Its record
(every RK4 step's state and torque) is held to ``hybrid.simulate``'s run of the same experiment as the
formula's closed loop is (``tests/test_closed_loop_c.py``): each state column relative to its largest magnitude
over the run, each torque relative to its joint's peak, to 1e-9 (5e-11 measured on the sphere's mesh over 1 s,
6e-12 on the link); the sensor's force the C plant gives at the C run's states to the run's force, relative to
its peak, to 1e-9; the printed metrics to 1e-9 relative. The parts: a sphere's mesh, and the Panda's fifth
link from example-robot-data (a CAD mesh nobody here designed, not a sphere). Damaged data files (cut short,
padded, a byte flipped, the other byte order, a grid that is not one) are refused by the C with a status, and
the struct keeps the part it had; a sensor tip beyond the part's band stops the C plant where the Python plant
stops. A raster across the sphere's mesh (a path task) is run in C as on a plane, every metric it prints (the
path's too) equal to the Python run's to 1e-9 relative (2e-11 measured).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import math
import subprocess
import zlib
from pathlib import Path

import numpy as np
import pytest
from test_closed_loop_c import (
    CPlant,
    assert_metrics,
    build_example,
    check_path_run,
    raster_experiment,
    run,
    run_against_simulate,
    worst,
)

import hybrid
from hybrid.spec.part import PART_DATA_HEADER, PART_GRID

trimesh = pytest.importorskip("trimesh")

CENTRE, RADIUS = np.array([0.5, 0.0, 0.2]), 0.15
#: the numbers before the coefficients in a data file
BODY = len(PART_DATA_HEADER) + len(PART_GRID)


def sphere_part(band: float | None = None, spacing: float = 0.006) -> hybrid.MeshSurface:
    mesh = trimesh.creation.icosphere(subdivisions=5, radius=RADIUS)
    mesh.apply_translation(CENTRE)
    return hybrid.MeshSurface(mesh.vertices, mesh.faces, spacing=spacing, band=band)


@pytest.fixture(scope="module")
def sphere():
    part = sphere_part()
    return hybrid.tracing_experiment(surface=part, duration=1.0,
                                     start_point=tuple(part.project(np.array([0.5, -0.05, 0.35]))))


@pytest.fixture(scope="module")
def link():
    """The Panda's fifth link (its collision mesh, 300 facets) in the UR5's reach, touched from 3 mm while moving
    at 5 cm/s along base x. (Not a speed step from rest: a tip starting to slide, the friction's tanh about zero
    speed, amplifies rounding; there the library's own two runners, compiled and Python, differ by 4e-7 of the
    tip's x velocity's scale, and the C lies between them.)"""
    from conftest import example_robot

    path = example_robot("panda_description/meshes/collision/link5.stl")
    place = trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0])
    place[:3, 3] = (0.45, 0.0, 0.15)
    part = hybrid.MeshSurface.from_file(path, transform=place, spacing=0.005)
    return hybrid.tracing_experiment(surface=part, start_point=tuple(part.project(np.array([0.45, 0.0, 0.25]))),
                                     duration=1.0, frame_direction=(1.0, 0.0, 0.0), start_gap=0.003,
                                     approach_speed=0.02, force_reference=10.0, speed_reference=0.05)


def build(exp, folder: Path) -> Path:
    """:func:`build_example` of a part's experiment, which writes the part's data file and header too."""
    build_example(exp, folder)
    assert {"ur5_part.bin", "hybrid_part.h", "ur5_plant.c", "ur5_controller.c"} <= {p.name for p in folder.iterdir()}
    return folder


def plant_with_part(folder: Path) -> tuple[CPlant, np.ndarray]:
    """The generated plant loaded, given the part's data file's numbers (returned: the struct points at them)."""
    c = CPlant(folder, "ur5_plant")
    data = np.fromfile(folder / "ur5_part.bin", "<f8")
    assert c.call("set_part", c.ffi.from_buffer("double[]", data), len(data)) == 0
    return c, data


@pytest.mark.parametrize("which", ["sphere", "link"])
def test_the_closed_loop_on_a_part_in_c_equals_simulate(which, request, tmp_path):
    exp = request.getfixturevalue(which)
    folder = build(exp, tmp_path)
    reference, metrics, record = run_against_simulate(folder, exp)
    nx = len(reference.state[0])
    dx, dtau = worst(record, reference, slice(None))
    assert dx < 1e-9 and dtau < 1e-9, (dx, dtau)
    assert_metrics(metrics, reference.metrics)
    assert metrics["contact_losses"] == 0 and reference.metrics["contact_losses"] == 0
    # the force: the C plant's sensor at the C run's states against the run's own
    c, _ = plant_with_part(folder)
    columns = [reference.record["outputs"].index(n) for n in ("Fc_x", "Fc_y", "Fc_z")]
    rows = np.arange(0, len(record), 7)
    force = np.empty((len(rows), 3))
    for i, r in enumerate(rows):
        c.ffi.memmove(c.p.x, c.ffi.from_buffer("double[]", record[r, 1:1 + nx].copy()), 8 * nx)
        status, wrench = c.out("wrench", 6)
        assert status == 0
        force[i] = wrench[:3]
    python = reference.outputs[rows][:, columns]
    assert np.max(np.abs(force - python)) / np.max(np.abs(python)) < 1e-9
    assert np.abs(python[:, 2]).max() > 5.0  # the run presses on the part


def test_a_raster_across_a_part_in_c_equals_simulate(sphere, tmp_path):
    """A path task on a part: ``test_closed_loop_c``'s raster drawn across the sphere's mesh."""
    part = sphere.surface
    exp = raster_experiment(part, part.project(np.array([0.47, -0.03, 0.36])))
    check_path_run(build(exp, tmp_path), exp)


def test_the_files_are_the_same_bytes_each_time(sphere, tmp_path):
    first = {p.name: p.read_bytes() for p in sphere.generate(tmp_path / "a", "same")}
    second = {p.name: p.read_bytes() for p in sphere.generate(tmp_path / "b", "same")}
    assert first == second
    assert set(first) == {f"same_{u}.{e}" for u in ("controller", "plant") for e in ("c", "h", "json")} | {
        "hybrid_part.h", "same_part.bin"}
    # the data file is the part's numbers (the C reads no others), its CRC-32 zlib's of them
    data = np.frombuffer(first["same_part.bin"], "<f8")
    grid, coefficients = sphere.surface.data()
    np.testing.assert_array_equal(data[len(PART_DATA_HEADER):BODY], grid)
    np.testing.assert_array_equal(data[BODY:], coefficients)
    assert data[PART_DATA_HEADER.index("crc32")] == zlib.crc32(first["same_part.bin"][8 * len(PART_DATA_HEADER):])
    # the plant's manifest names the part by its file (not by the mesh the experiment holds)
    surface = json.loads(first["same_plant.json"])["experiment"]["surface"]
    assert surface["data_sha256"] == hashlib.sha256(first["same_part.bin"]).hexdigest()
    assert "vertices" not in surface
    # one build serves every part: the C holds none of its numbers
    assert all(len(first[n]) < 0.1 * len(first["same_part.bin"]) for n in first if not n.endswith(".bin"))
    with pytest.raises(hybrid.HybridError, match="exists"):
        sphere.surface.save_data(tmp_path / "a" / "same_part.bin")
    assert sphere.surface.save_data(tmp_path / "a" / "same_part.bin", overwrite=True).read_bytes() == first[
        "same_part.bin"]
    (tmp_path / "a" / "same_part.bin").write_bytes(b"another part")
    with pytest.raises(hybrid.HybridError, match="same_part.bin already exist"):
        sphere.generate(tmp_path / "a", "same")


def damaged(data: np.ndarray) -> dict[str, np.ndarray]:
    """The data file's numbers damaged as a copy, a disk or a caller damages them, by what was done."""
    raw = data.tobytes()
    flipped = bytearray(raw)
    flipped[8 * BODY + 8 * 1000 + 3] ^= 0x10  # a bit of a coefficient
    cells = data.copy()
    cells[len(PART_DATA_HEADER) + PART_GRID.index("cells_z")] -= 1.0  # a grid the coefficients are not
    unspaced = data.copy()
    unspaced[len(PART_DATA_HEADER) + PART_GRID.index("spacing")] = -unspaced[
        len(PART_DATA_HEADER) + PART_GRID.index("spacing")]
    crc = PART_DATA_HEADER.index("crc32")
    unspaced[crc] = zlib.crc32(unspaced[len(PART_DATA_HEADER):].tobytes())  # its CRC made to match
    count = data.copy()
    count[PART_DATA_HEADER.index("coefficients")] += 1.0
    return {"cut short": data[:-1], "padded": np.append(data, 0.0), "a bit flipped": np.frombuffer(flipped, "<f8"),
            "the other byte order": data.byteswap(), "the grid's cells changed": cells,
            "a negative spacing, its CRC matching": unspaced, "the header's count changed": count,
            "the header only": data[:BODY - 1], "another file": np.zeros_like(data)}


def test_damaged_data_are_refused_by_the_c_with_a_status(sphere, tmp_path):
    from test_standalone_controller import CController

    folder = tmp_path
    sphere.generate(folder, "ur5")
    c = CPlant(folder, "ur5_plant")
    invalid = c.lib.UR5_PLANT_PARAMETER_INVALID
    tau = np.zeros(6)
    x0 = c.array("x")
    # no part given: nothing advances, nothing is read
    assert c.advance(tau, 3) == invalid and c.p.steps == 0
    np.testing.assert_array_equal(c.array("x"), x0)
    status, y = c.out("outputs", c.lib.UR5_PLANT_NY)
    assert status == invalid and np.isnan(y).all()
    assert c.call("set_part", c.ffi.NULL, 100) == invalid
    good = np.fromfile(folder / "ur5_part.bin", "<f8")
    for what, bad in damaged(good).items():
        bad = np.ascontiguousarray(bad)
        assert c.call("set_part", c.ffi.from_buffer("double[]", bad), len(bad)) == invalid, what
        assert c.p.part_grid == c.ffi.NULL, what
    # the controller alone (Controller.generate writes its part's data file too) refuses them alike
    written = {p.name for p in sphere.build_controller().generate(folder, "ctl")}
    assert {"ctl_part.bin", "hybrid_part.h"} <= written
    assert (folder / "ctl_part.bin").read_bytes() == good.tobytes()
    ctrl = CController(folder, "ctl")
    for what, bad in damaged(good).items():
        bad = np.ascontiguousarray(bad)
        status = ctrl.lib.ctl_controller_set_part(ctrl.c, ctrl.ffi.from_buffer("double[]", bad), len(bad))
        assert ctrl.name(status) == "PARAMETER_INVALID", what
        assert ctrl.c.part_grid == ctrl.ffi.NULL, what
    assert ctrl.lib.ctl_controller_set_part(ctrl.c, ctrl.ffi.from_buffer("double[]", good), len(good)) == 0
    assert ctrl.c.part_grid != ctrl.ffi.NULL
    # given, then refused another: the struct keeps the part it had, and runs on as the Python plant does
    assert c.call("set_part", c.ffi.from_buffer("double[]", good), len(good)) == 0
    bad = damaged(good)["a bit flipped"].copy()
    assert c.call("set_part", c.ffi.from_buffer("double[]", bad), len(bad)) == invalid
    py, x = sphere.plant(), sphere.initial_state()
    tau = np.linspace(-2.0, 3.0, 6)
    trajectory = np.empty((200, len(x)))
    assert py.advance(x, tau, 200, trajectory) == 200
    assert c.advance(tau, 200) == 0
    np.testing.assert_allclose(c.array("x"), x, rtol=1e-12, atol=1e-13)
    status, y = c.out("outputs", c.lib.UR5_PLANT_NY)
    assert status == 0
    np.testing.assert_allclose(y, py.outputs(x[None, :])[0], rtol=1e-12, atol=1e-12)
    # the sensor tip beyond the band (at the sphere's centre): the Python plant takes no step, nor does the C
    x[12:15] = CENTRE
    c.ffi.memmove(c.p.x, c.ffi.from_buffer("double[]", x), 8 * len(x))
    assert py.advance(x.copy(), tau, 5, np.empty((5, len(x)))) == 0
    steps = c.p.steps
    assert c.advance(tau, 5) == c.lib.UR5_PLANT_FRAME_UNDEFINED and c.p.steps == steps
    np.testing.assert_array_equal(c.array("x"), x)
    status, y = c.out("outputs", c.lib.UR5_PLANT_NY)
    assert status == c.lib.UR5_PLANT_FRAME_UNDEFINED
    np.testing.assert_allclose(y, py.outputs(x[None, :])[0], rtol=1e-12, atol=1e-12)  # NaN where it reads the part
    assert np.isnan(y).any() and np.isfinite(y).any()


def test_the_loop_refuses_a_damaged_file_and_takes_another_part(sphere, tmp_path):
    """The example's loop stops with the C's refusal of a damaged file; with another part's file the same build
    runs on that part: the compiled loop's run of the experiment on it, from the build's start state."""
    from hybrid.simulation import closed_loop

    folder = build(sphere, tmp_path)
    good = (folder / "ur5_part.bin").read_bytes()
    (folder / "short.bin").write_bytes(good[:-5])
    for name, message in (("short.bin", "PARAMETER_INVALID"), ("missing.bin", "missing.bin")):
        done = subprocess.run([str(folder / "closed_loop"), "--part", name], cwd=folder, capture_output=True,
                              text=True, timeout=60)
        assert done.returncode == 1 and message in done.stderr, done.stderr
    finer = sphere_part(spacing=0.005)  # the sphere's mesh fitted again: other numbers, another grid
    finer.save_data(folder / "finer.bin")
    assert finer.data()[0].tolist() != sphere.surface.data()[0].tolist()
    other = dataclasses.replace(sphere, surface=finer, duration=0.3)
    want = closed_loop.run([closed_loop.prepare(other, x0=sphere.initial_state())], record=True)[0]
    assert want.status == 0
    metrics = run(folder, "--part", "finer.bin", "--duration", "0.3", "--record", "finer.run")
    record = np.fromfile(folder / "finer.run").reshape(-1, 1 + 18 + 6)
    assert record.shape[0] == 3001
    scale = np.max(np.abs(want.states), axis=0)
    assert np.max(np.abs(record[:, 1:19] - want.states) / scale) < 1e-9
    assert_metrics(metrics, want.metrics)


def test_a_tip_leaving_the_band_stops_the_c_where_simulate_stops(tmp_path):
    """A part fitted with a narrow band, the sensor soft: the arm tip (behind the sensor) leaves the band. The C's
    loop stops at the sample where simulate stops, with the controller's FRAME_UNDEFINED."""
    narrow = sphere_part(band=0.01, spacing=0.008)
    exp = hybrid.tracing_experiment(surface=narrow, duration=1.0,
                                    start_point=tuple(narrow.project(np.array([0.5, -0.05, 0.35]))),
                                    sensor=hybrid.Sensor(stiffness=300.0))
    with pytest.raises(hybrid.SimulationError) as info:
        hybrid.simulate(exp)
    folder = build(exp, tmp_path)
    done = subprocess.run([str(folder / "closed_loop")], cwd=folder, capture_output=True, text=True, timeout=60)
    assert done.returncode == 1
    assert "FRAME_UNDEFINED" in done.stderr
    stopped = float(done.stderr.split("t = ")[1].split()[0])
    assert stopped == pytest.approx(info.value.time, abs=1e-9)


def test_a_controller_told_another_surface_is_refused(sphere, tmp_path):
    exp = hybrid.tracing_experiment(surface=sphere.surface, controller_surface=hybrid.Sphere(tuple(CENTRE), RADIUS),
                                    start_point=sphere.start_point, duration=0.1)
    with pytest.raises(hybrid.HybridError, match="controller_surface"):
        exp.generate(tmp_path)
