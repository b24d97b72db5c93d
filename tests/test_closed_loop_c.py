"""The closed loop in C alone (examples/closed_loop_c) is ``hybrid.simulate``'s run, and the standalone
plant is the Python plant.

The example is generated with the command its README gives, built with ``-std=c99 -Wall -Wextra
-Werror -pedantic`` and run for the tracing experiment's 3 s. Its record (every RK4 step's state and
torque) is compared with ``hybrid.simulate(hybrid.tracing_experiment(duration=3.0))``'s: each state
column relative to the column's largest magnitude over the run, each torque relative to its joint's
peak, to 1e-9 (about 1e-11 is measured); its printed metrics with ``result.metrics`` to 1e-9 relative.
So is a run along a path task (a raster on a plane, pressed, released at its end and left along the
normal): its metrics are taken against the experiment's references, not the controller's steps (zero
there: the follower gives the references), and the path's (``path_*``) are printed too, each equal to
``result.metrics``' to 1e-9 relative (3e-10 measured, a joint's peak torque of 1e-7 N m; the path's 1e-12),
and so along a closed path (Khatib's scheme), a spiral on a sphere the run ends on, and the Panda's raster
across its pillar (2e-10 measured).
The plant alone (compiled, loaded with cffi) gives the Python plant's start state, sensor wrench,
record and RK4 steps, for the UR5, the Panda and the planar arm's closed form.
"""

from __future__ import annotations

import json
import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

import cffi
import numpy as np
import pytest

import hybrid
from hybrid.spec.interfaces import STATUS_CODES
from hybrid.spec.metrics import PATH_METRICS

EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "closed_loop_c"
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
NX, NQ = 18, 6


@pytest.fixture(scope="module")
def example(tmp_path_factory):
    """The example generated (the README's command), built strictly: its folder."""
    folder = tmp_path_factory.mktemp("closed_loop_c")
    shutil.copy(EXAMPLE / "main.c", folder / "main.c")
    done = subprocess.run([sys.executable, "-m", "hybrid", "generate", "--experiment", "tracing", "--set",
                           "duration=3.0", "--out", str(folder), "--name", "ur5"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    build = subprocess.run(["gcc", *STRICT, "-O2", "main.c", "ur5_controller.c", "ur5_plant.c", "-lm", "-o",
                            "closed_loop"], cwd=folder, capture_output=True, text=True)
    assert build.returncode == 0, build.stderr
    return folder


@pytest.fixture(scope="module")
def reference():
    return hybrid.simulate(hybrid.tracing_experiment(duration=3.0))


def run(folder: Path, *args: str) -> dict:
    done = subprocess.run([str(folder / "closed_loop"), *args], cwd=folder, capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    return {name: float(value) for name, value in re.findall(r"^(\w+) (\S+)$", done.stdout, flags=re.M)}


def worst(record: np.ndarray, res, rows) -> tuple[float, float]:
    """The largest difference of the record's states and torques from the run's, each column relative to
    its scale (its largest magnitude over the run); the record's torque acts from its row's time on,
    the run's up to it."""
    nx = res.state.shape[1]  # the UR5's 18, the Panda's 20
    x, tau = record[:, 1:1 + nx], record[:, 1 + nx:]
    np.testing.assert_array_equal(record[:, 0], res.t[rows])
    state_scale = np.max(np.abs(res.state), axis=0)
    dx = np.max(np.abs(x - res.state[rows]) / state_scale)
    acting = np.vstack([res.tau[1:], res.tau[-1:]])[rows]
    dtau = np.max(np.abs(tau - acting) / np.max(np.abs(res.tau), axis=0))
    return float(dx), float(dtau)


def assert_metrics(printed: dict, metrics: dict) -> None:
    """The example's printed metrics are ``metrics`` (NaN where they are), to 1e-9 relative."""
    assert set(printed) == set(metrics)
    for name, value in metrics.items():
        if math.isnan(value):
            assert math.isnan(printed[name]), name
        else:
            assert printed[name] == pytest.approx(value, rel=1e-9, abs=1e-12), name


def test_example_equals_simulate(example, reference):
    metrics = run(example, "--record", "run.bin")
    record = np.fromfile(example / "run.bin").reshape(-1, 1 + NX + NQ)
    assert record.shape[0] == len(reference.t) == 30001
    dx, dtau = worst(record, reference, slice(None))
    assert dx < 1e-9 and dtau < 1e-9, (dx, dtau)
    assert_metrics(metrics, reference.metrics)
    assert metrics["contact_losses"] == 0 and abs(metrics["steady_state_force_error_N"]) < 0.05


def test_example_records_per_sample_as_csv_and_runs_shorter(example, reference):
    metrics = run(example, "--duration", "0.5", "--per-sample", "--record", "run.csv")
    record = np.loadtxt(example / "run.csv", delimiter=",")
    assert record.shape == (51, 1 + NX + NQ)
    rows = np.r_[0:5000:100, 5000]
    dx, dtau = worst(record[:-1], reference, rows[:-1])
    assert dx < 1e-9 and dtau < 1e-9
    np.testing.assert_allclose(record[-1, 1:1 + NX], reference.state[5000], rtol=1e-9, atol=1e-12)
    short = hybrid.simulate(hybrid.tracing_experiment(duration=0.5)).metrics
    assert_metrics(metrics, short)
    assert math.isnan(metrics["force_deviation_after_speed_step_N"])  # the speed steps at 1.5 s


def build_example(exp, folder: Path) -> Path:
    """``exp`` generated as ``ur5`` into ``folder`` beside the example's loop, built strictly: the folder."""
    exp.generate(folder, "ur5")
    shutil.copy(EXAMPLE / "main.c", folder / "main.c")
    done = subprocess.run(["gcc", *STRICT, "-O2", "main.c", "ur5_controller.c", "ur5_plant.c", "-lm", "-o",
                           "closed_loop"], cwd=folder, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return folder


def raster_experiment(surface, corner, **settings) -> hybrid.Experiment:
    """Two passes of 4 cm, 1 cm apart, across ``surface`` from ``corner`` at 0.1 m/s and 10 N; the force released
    at the end and the tip left 3 mm along the normal, then held there."""
    raster = hybrid.RasterPath(surface, corner, (1.0, 0.0, 0.0), pass_length=0.04, spacing=0.01, passes=2)
    task = hybrid.PathTask(raster, speed=0.1, force=10.0, retreat_distance=0.003)
    return hybrid.tracing_experiment(surface=surface, path_task=task, duration=2.0, **settings)


def run_against_simulate(folder: Path, exp) -> tuple:
    """``hybrid.simulate(exp)``, and the example built in ``folder`` for ``exp`` run with its record: the Python
    run, the printed metrics and the record (a row per RK4 step, as many as the run's)."""
    reference = hybrid.simulate(exp)
    metrics = run(folder, "--record", "run.bin")
    nx, nq = len(reference.state[0]), len(reference.tau[0])
    record = np.fromfile(folder / "run.bin").reshape(-1, 1 + nx + nq)
    assert record.shape[0] == len(reference.t)
    return reference, metrics, record


def matches_simulate(folder: Path, exp) -> dict:
    """The example built in ``folder`` for ``exp`` (a path task), run: its record is ``hybrid.simulate``'s, every
    metric it prints (the path's too) ``result.metrics``'; the printed metrics."""
    reference, metrics, record = run_against_simulate(folder, exp)
    nx = len(reference.state[0])
    dx, _ = worst(record, reference, slice(None))
    # the torques relative to the largest joint's peak (the last joint's, about 1e-7 N m here, is rounding's);
    # the state to 1e-8 of each column's scale: where the tip stops at the path's end, the friction's tanh about
    # zero speed amplifies rounding in the sensor tip's velocity (1e-9 of its scale measured on the sphere's
    # mesh, 1e-11 on the plane; every other column within 2e-12)
    acting = np.vstack([reference.tau[1:], reference.tau[-1:]])
    dtau = np.max(np.abs(record[:, 1 + nx:] - acting)) / np.max(np.abs(reference.tau))
    assert dx < 1e-8 and dtau < 1e-9, (dx, dtau)
    assert {m.name for m in PATH_METRICS} <= set(metrics)
    assert_metrics(metrics, reference.metrics)
    return metrics


def check_path_run(folder: Path, exp) -> dict:
    """:func:`matches_simulate`, and the raster completed within the run, its force released, the tip off the
    surface at the end; the printed metrics."""
    metrics = matches_simulate(folder, exp)
    # the run did what the metrics say: the raster completed within the run, its force released, the tip 3 mm off
    # the surface at the end; the force error over the last 0.2 s is then the task's whole force, as
    # hybrid.metrics takes it (the experiment's reference, not the controller's steps, 0 on a path task)
    task = exp.path_task
    assert metrics["path_travelled_m"] == pytest.approx(task.path.length, abs=1e-9)
    assert 0 < metrics["path_time_s"] < exp.duration and metrics["path_end_peak_force_N"] < 1.05 * task.force
    assert metrics["path_error_rms_m"] < 1e-3 and metrics["path_contact_losses"] == 0
    assert exp.force_reference.after == task.force
    assert metrics["steady_state_force_error_N"] == pytest.approx(task.force, abs=0.5)
    return metrics


def test_example_along_a_path_task_equals_simulate(tmp_path):
    plane = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))
    exp = raster_experiment(plane, plane.project(np.array([0.45, -0.05, 0.1])))
    check_path_run(build_example(exp, tmp_path), exp)


def closed_circle() -> hybrid.Experiment:
    """A closed path, one lap of eight waypoints on a circle of 2 cm on the tilted plane, under Khatib's scheme."""
    plane = hybrid.Plane((0.4, 0.0, 0.1), (0.0, 0.6, 0.8))
    points = [plane.project(np.array([0.47 + 0.02 * math.cos(a), 0.02 * math.sin(a), 0.1]))
              for a in np.linspace(0.0, 2 * math.pi, 8, endpoint=False)]
    task = hybrid.PathTask(hybrid.WaypointPath(plane, points, closed=True), speed=0.1, force=10.0, laps=1.0,
                           retreat_distance=0.003)
    return hybrid.tracing_experiment(surface=plane, path_task=task, duration=2.0, controller="khatib")


def spiral_cut_short() -> hybrid.Experiment:
    """A spiral on the analytic sphere, the run ending (1 s) before the spiral (0.24 m at 8 cm/s) does."""
    sphere = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)
    spiral = hybrid.SpiralPath(sphere, sphere.project(np.array([0.45, 0.0, 0.4])), 0.01, 1.5, start_radius=0.01)
    task = hybrid.PathTask(spiral, speed=0.08, force=10.0, retreat_distance=0.003)
    return hybrid.tracing_experiment(surface=sphere, path_task=task, duration=1.0)


def panda_raster() -> hybrid.Experiment:
    """The Panda (seven joints, its posture task) along a raster across its pillar, released and backed off."""
    pillar = hybrid.Cylinder((0.67, 0.0, 0.0), (0.0, 0.0, 1.0), 0.25)
    raster = hybrid.RasterPath(pillar, pillar.project(np.array([0.42, 0.0, 0.78])), (0.0, -1.0, 0.0),
                               pass_length=0.03, spacing=0.01, passes=2)
    task = hybrid.PathTask(raster, speed=0.05, force=10.0, retreat_distance=0.003)
    return hybrid.panda_experiment(path_task=task, duration=2.0)


OTHER_PATHS = {"a closed path, khatib": closed_circle, "a spiral on a sphere, cut short": spiral_cut_short,
               "the Panda, a raster on a cylinder": panda_raster}


@pytest.mark.parametrize("case", list(OTHER_PATHS))
def test_example_along_other_path_tasks_equals_simulate(case, tmp_path):
    """The raster's comparison on a closed path, a path the run ends on and another arm and surface: every
    metric printed is ``simulate``'s, those of a path not finished (its time, its end's force) NaN alike."""
    exp = OTHER_PATHS[case]()
    metrics = matches_simulate(build_example(exp, tmp_path), exp)
    task, length = exp.path_task, exp.path_task.path.length
    finished = metrics["path_travelled_m"] >= length - 1e-3
    assert finished == (case != "a spiral on a sphere, cut short")
    assert math.isnan(metrics["path_time_s"]) != finished and math.isnan(metrics["path_end_peak_force_N"]) != finished
    if finished:  # released at the end, and off the surface over the last 0.2 s
        assert metrics["path_end_peak_force_N"] < 1.05 * task.force
        assert metrics["steady_state_force_error_N"] == pytest.approx(task.force, abs=0.5)
    assert metrics["path_error_rms_m"] < 1e-3 and metrics["path_contact_losses"] == 0


def test_example_refuses_bad_arguments(example):
    for args in (["--duration", "-1"], ["--duration", "x"], ["--bogus"], ["--record"]):
        done = subprocess.run([str(example / "closed_loop"), *args], capture_output=True, text=True)
        assert done.returncode == 2 and "usage" in done.stderr


# ------------------------------------------------------------------- the plant alone


class CPlant:
    """A standalone plant compiled and loaded (cffi, ABI mode)."""

    def __init__(self, folder: Path, prefix: str):
        header = (folder / f"{prefix}.h").read_text()
        lib = folder / f"lib{prefix}.so"
        subprocess.run(["gcc", *STRICT, "-O2", "-shared", "-fPIC", str(folder / f"{prefix}.c"), "-o", str(lib),
                        "-lm"], check=True, capture_output=True)
        ffi = cffi.FFI()
        body = "\n".join(line for line in header.split("*/", 1)[1].splitlines()
                         if not re.match(r"\s*#(ifndef|endif|define \w+_H\b|include)", line))
        ffi.cdef(re.sub(r"/\*.*?\*/", "", body, flags=re.S))
        self.ffi, self.lib, self.prefix = ffi, ffi.dlopen(str(lib)), prefix
        self.p = ffi.new(f"{prefix} *")
        self.call("init")
        self.nx = getattr(self.lib, f"{prefix.upper()}_NX")

    def call(self, name: str, *args):
        return getattr(self.lib, f"{self.prefix}_{name}")(self.p, *args)

    def array(self, field: str) -> np.ndarray:
        return np.frombuffer(self.ffi.buffer(getattr(self.p, field)), float).copy()

    def out(self, name: str, n: int) -> tuple[int, np.ndarray]:
        v = np.empty(n)
        return self.call(name, self.ffi.from_buffer("double[]", v)), v

    def advance(self, tau, n: int) -> int:
        return self.call("advance", self.ffi.from_buffer("double[]", np.ascontiguousarray(tau, float)), n)


@pytest.mark.parametrize("make, name", [(lambda: hybrid.tracing_experiment(duration=0.5), "ur5"),
                                        (lambda: hybrid.panda_experiment(duration=0.4), "panda"),
                                        (lambda: hybrid.paper_experiment(), "paper")])
def test_plant_equals_python(tmp_path, make, name):
    exp = make()
    exp.generate(tmp_path, name)
    c, py = CPlant(tmp_path, f"{name}_plant"), exp.plant()
    x0 = exp.initial_state()
    np.testing.assert_array_equal(c.array("x0"), x0)
    np.testing.assert_array_equal(c.array("x"), x0)
    assert (c.p.h, c.p.steps_per_sample, c.p.sample_time, c.p.duration) == (
        exp.integration_step, exp.steps_per_sample, exp.sample_time, exp.duration)
    # off the rest state: a torque held over 300 steps, against the Python plant's RK4
    tau = np.linspace(-2.0, 3.0, py.nq)
    x, trajectory = x0.copy(), np.empty((300, len(x0)))
    assert py.advance(x, tau, 300, trajectory) == 300
    assert c.advance(tau, 300) == 0 and c.p.steps == 300
    np.testing.assert_allclose(c.array("x"), x, rtol=1e-12, atol=1e-13)
    status, wrench = c.out("wrench", 6)
    assert status == 0
    np.testing.assert_allclose(wrench, py.sensor_wrench(x), rtol=1e-12, atol=1e-12)
    status, y = c.out("outputs", len(py.record["outputs"]))
    np.testing.assert_allclose(y, py.outputs(x[None, :])[0], rtol=1e-12, atol=1e-12)
    _, s = c.out("signals", 4)
    names = list(py.record["outputs"])
    np.testing.assert_array_equal(s, y[[names.index(k) for k in ("Fc_n", "v_t", "penetration", "N")]])
    c.call("reset")
    np.testing.assert_array_equal(c.array("x"), x0)
    assert c.p.steps == 0


def test_plant_statuses_and_bytes(tmp_path):
    exp = hybrid.paper_experiment()
    exp.generate(tmp_path / "a", "same")
    exp.generate(tmp_path / "b", "same")
    for n in ("same_plant.c", "same_plant.h", "same_plant.json", "same_controller.c", "same_controller.h"):
        assert (tmp_path / "a" / n).read_bytes() == (tmp_path / "b" / n).read_bytes()
    c = CPlant(tmp_path / "a", "same_plant")
    name = c.lib.same_plant_status_name
    x = c.array("x")
    assert c.advance([np.nan, 0.0], 5) == c.lib.SAME_PLANT_INPUT_NONFINITE and c.p.steps == 0
    np.testing.assert_array_equal(c.array("x"), x)
    assert c.advance([1e300, 1e300], 50) == c.lib.SAME_PLANT_NONFINITE  # a torque no arm takes
    assert np.isfinite(c.array("x")).all() and c.p.steps < 50  # the last finite state, the steps it took
    # the numbers are the one table's (as every unit's), each named as it is declared; another is unknown
    codes = [STATUS_CODES[n] for n in ("OK", "NONFINITE", "INPUT_NONFINITE")] + [1, 99]
    assert [c.ffi.string(name(i)).decode() for i in codes] == ["OK", "NONFINITE", "INPUT_NONFINITE", "UNKNOWN",
                                                               "UNKNOWN"]
    with pytest.raises(hybrid.HybridError, match="--force"):
        hybrid.paper_experiment(KPf=3.0).generate(tmp_path / "a", "same")
    with pytest.raises(hybrid.HybridError, match="cannot name C symbols"):
        exp.generate(tmp_path / "c", "1bad")


def test_generate_command_sets_and_refuses(tmp_path, capsys):
    from hybrid.cli.main import main

    assert main(["generate", "--experiment", "paper", "--set", "contact.friction=0.05", "--set", "KPf=3",
                 "--set", "controller=khatib", "--set", "F_d={before = 8.0, after = 12.0, at = 0.3}", "--out",
                 str(tmp_path), "--name", "pk"]) == 0
    plant = json.loads((tmp_path / "pk_plant.json").read_text())
    controller = json.loads((tmp_path / "pk_controller.json").read_text())
    exp = hybrid.paper_experiment(contact=hybrid.Contact(friction=0.05), KPf=3.0, controller="khatib",
                                  F_d=hybrid.Step(8.0, 12.0, 0.3))
    assert plant["configuration"]["plant"] == exp.plant_array().tolist()
    assert plant["configuration"]["x0"] == exp.initial_state().tolist()
    assert controller["scheme"] == "khatib"
    assert controller["configuration"]["gains"] == exp.build_controller().step_inputs()["gains"].tolist()
    capsys.readouterr()
    for args, message in (
            (["--experiment", "paper", "--urdf", "x.urdf"], "one or the other"),
            (["--set", "KPf=3"], "give --experiment too"),
            ([], "--urdf and --tip"),
            (["--experiment", "paper", "--set", "KPf"], "KEY=VALUE"),
            (["--experiment", "paper", "--set", "KPf=1", "--set", "KPf=2"], "twice"),
            (["--experiment", "paper", "--set", "bogus=1"], "unknown setting"),
            (["--experiment", "tracing", "--set", "contact.bogus=1"], "unknown setting"),
            # a path task is made in Python: neither a table nor text sets one
            (["--experiment", "tracing", "--set", "path_task={speed = 0.1}"], "Experiment.generate"),
            (["--experiment", "tracing", "--set", "path_task=raster"], "made in Python (hybrid.PathTask)"),
            (["--experiment", "paper", "--set", "KPf=4"], "--force")):
        assert main(["generate", *args, "--out", str(tmp_path), "--name", "pk"]) == 2, args
        assert message in capsys.readouterr().err, args


# ------------------------------------------------------------------ the ros2_control-shaped wrapper

ROS2_LIKE = EXAMPLE.parent / "ros2_like"


@pytest.fixture(scope="module")
def ros2_like(example):
    """examples/ros2_like built with ``g++ -std=c++17 -Wall -Wextra -Werror`` on the example's generated C."""
    for name in ("main.cpp", "hybrid_controller.hpp"):
        shutil.copy(ROS2_LIKE / name, example / name)
    for unit in ("ur5_controller", "ur5_plant"):
        subprocess.run(["gcc", *STRICT, "-O2", "-c", f"{unit}.c", "-o", f"{unit}.o"], cwd=example, check=True)
    build = subprocess.run(["g++", "-std=c++17", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2", "main.cpp",
                            "ur5_controller.o", "ur5_plant.o", "-o", "ros2_like"], cwd=example, capture_output=True,
                           text=True)
    assert build.returncode == 0, build.stderr
    return example / "ros2_like"


def periods(program: Path, *args: str) -> list[dict]:
    done = subprocess.run([str(program), *args], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    rows = []
    for line in done.stdout.splitlines():
        k, t, updated, result, status, *numbers = line.split(",")
        v = np.array(numbers, float)
        rows.append({"k": int(k), "t": float(t), "updated": updated == "1", "result": result, "status": status,
                     "q": v[:NQ], "qd": v[NQ:2 * NQ], "wrench": v[2 * NQ:2 * NQ + 6], "effort": v[2 * NQ + 6:]})
    return rows


def python_torque(ctrl, row):
    """The Python controller's torque for the period's update (None where it refuses the sample)."""
    try:
        return ctrl(row["t"], row["q"], row["qd"], row["wrench"])
    except hybrid.HybridError:
        return None


def test_ros2_like_equals_python(ros2_like):
    rows = periods(ros2_like, "--samples", "300")
    assert len(rows) == 300 and all(r["result"] == "OK" and r["status"] == "OK" for r in rows)
    ctrl = hybrid.tracing_experiment(duration=3.0).build_controller()
    worst_tau = 0.0
    for r in rows:
        tau = python_torque(ctrl, r)
        worst_tau = max(worst_tau, float(np.max(np.abs(r["effort"] - tau)) / np.max(np.abs(tau))))
    assert worst_tau < 1e-12


def test_ros2_like_holds_the_last_effort_on_error(ros2_like):
    rows = periods(ros2_like, "--samples", "200", "--miss", "100", "--nan", "150")
    expected = {100: ("-", "-"), 101: ("ERROR", "SAMPLE_LATE"), 150: ("ERROR", "INPUT_NONFINITE"),
                151: ("ERROR", "SAMPLE_LATE")}  # after a NaN the step's clock has not moved: one period late
    for r in rows:
        assert (r["result"], r["status"]) == expected.get(r["k"], ("OK", "OK")), r["k"]
    for k, held in ((100, 99), (101, 99), (150, 149), (151, 149)):
        np.testing.assert_array_equal(rows[k]["effort"], rows[held]["effort"])
    assert np.isnan(rows[150]["wrench"][0])
    # the samples it took, as the Python controller takes them: the same torques where both go on
    ctrl = hybrid.tracing_experiment(duration=3.0).build_controller()
    for r in rows:
        if not r["updated"]:
            continue
        tau = python_torque(ctrl, r)
        assert (tau is None) == (r["result"] == "ERROR"), r["k"]
        if tau is not None:
            np.testing.assert_allclose(r["effort"], tau, rtol=1e-12, atol=1e-12 * np.max(np.abs(tau)))


def test_ros2_like_refuses_bad_arguments(ros2_like):
    for args in (["--samples"], ["--miss", "x"], ["--bogus", "1"], ["--nan", "-2"]):
        done = subprocess.run([str(ros2_like), *args], capture_output=True, text=True)
        assert done.returncode == 2 and "usage" in done.stderr
