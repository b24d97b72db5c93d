"""The model the controller is told, identified from the arm's own data: a study on the UR5 and the Panda.

    python examples/studies/identification_study.py --out DIR [--quick]

The "real arm" is the shipped UR5 or Panda with every link's mass, centre of mass and inertia perturbed by
up to 30 % (:func:`hybrid.perturbed_robot`, each link still a rigid body) and friction on every joint that
its URDF does not have: a viscosity, a Coulomb friction (smooth sign of speed 0.05 rad/s) and an offset, each
drawn at random as a share of the joint's effort limit (viscosity 0.5-2 % per rad/s, Coulomb 1-4 %, offset
within +-1 %). Its torques along a trajectory are its inverse dynamics (the robot's regressor times its
parameters, which ``tests/test_regressor.py`` checks against Pinocchio) plus noise: Gaussian, 0.5 % of each
joint's effort limit on the torques and 1e-4 rad on the positions.

1. **Excite**: :func:`hybrid.excitation_trajectory` on the URDF's robot (period 10 s, 5 harmonics, the URDF's
   limits times 0.9, 2 rad/s^2), logged at 1 kHz for two periods.
2. **Identify**: :func:`hybrid.identify_dynamics` from the log's times, positions and torques alone
   (its default filter and differences, the physically consistent estimate).
3. **Validate**: on two other trajectories (another excitation's seed and period, and a sum of sines), the
   RMS error of the torques each model predicts against the real arm's (noise-free), per joint in % of the
   joint's torque range there: the identified model, the URDF's.
4. **Closed loop**: the arm's 3-D experiment (the UR5 on the sphere, the Panda on the pillar) with the real
   arm as the plant, a constant normal force of 15 N and the speed stepping from 0.05 to 0.3 m/s at 0.5 s
   (2 s), sampled at 1 kHz: the controller told the real arm (exact), the identified model, the URDF's;
   the normal force's and the speed's RMS errors.

Writes ``runs.csv`` (one row per arm and model told), ``study.json`` (the same and the validation's numbers),
``table.md`` and ``identification.png`` (the closed loop's normal force per model; the validation's torque
error per joint) into ``--out``.
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import time
from pathlib import Path

import numpy as np

import hybrid

#: the friction drawn for the real arm, as shares of each joint's effort limit: viscosity per rad/s, Coulomb,
#: offset (the offset's range is symmetric); its smooth sign's speed is the library's default, the one the
#: identification's regressor takes from the URDF's robot
VISCOSITY, COULOMB, OFFSET = (0.005, 0.02), (0.01, 0.04), 0.01
#: the measurement noise: the torques' standard deviation as a share of the effort limit, the positions' [rad]
TORQUE_NOISE, POSITION_NOISE = 0.005, 1e-4
#: the log's sample rate [Hz] and length [periods]
RATE, PERIODS = 1000.0, 2
#: the closed loop's references: a constant force [N], the speed's step [m/s] and when [s], the duration [s]; its
#: sample time [s], a real arm's control rate (at the paper's 10 ms the friction, cancelled once a sample
#: on the light wrists, makes the loops unstable: hybrid.stability says so)
FORCE, SPEEDS, STEP_AT, DURATION, SAMPLE_TIME = 15.0, (0.05, 0.3), 0.5, 2.0, 1e-3
ARMS = {"ur5": (hybrid.ur5, hybrid.tracing_experiment), "panda": (hybrid.panda, hybrid.panda_experiment)}


def real_arm(nominal: hybrid.Robot, seed: int) -> hybrid.Robot:
    """The URDF's robot with its inertial parameters perturbed by up to 30 % and friction drawn on its joints."""
    rng = np.random.default_rng(seed)
    effort = np.asarray(nominal.limits.effort, float)
    real = hybrid.perturbed_robot(nominal, 0.3, seed=seed)
    return dataclasses.replace(real, damping=tuple(effort * rng.uniform(*VISCOSITY, nominal.n)),
                               coulomb=tuple(effort * rng.uniform(*COULOMB, nominal.n)),
                               offset=tuple(effort * rng.uniform(-OFFSET, OFFSET, nominal.n)))


def pseudo_inertia(link) -> np.ndarray:
    """A link's ``[[Sigma, m c], [(m c)^T, m]]`` about its joint frame's origin (``Sigma = int p p^T dm``):
    positive definite exactly when a rigid body of positive density has the link's parameters."""
    m, c, Ic = link.mass, np.asarray(link.com), np.asarray(link.inertia)
    sigma = np.trace(Ic) / 2 * np.eye(3) - Ic + m * np.outer(c, c)
    return np.block([[sigma, m * c[:, None]], [m * c[None, :], np.array([[m]])]])


def inverse_dynamics(robot: hybrid.Robot, q, qd, qdd) -> np.ndarray:
    Y, _ = hybrid.regressor(robot, q, qd, qdd)
    return Y @ hybrid.linear_parameters(robot)


def log(traj, real: hybrid.Robot, rng) -> dict:
    """The real arm's log along ``traj``: times, noisy positions and torques (and the exact motion)."""
    t = np.arange(0.0, PERIODS * traj.period, 1.0 / RATE)
    q, qd, qdd = traj.sample(t)
    tau = inverse_dynamics(real, q, qd, qdd)
    effort = np.asarray(real.limits.effort, float)
    return {"t": t, "q": q + rng.normal(0, POSITION_NOISE, q.shape), "tau": tau + rng.normal(0, 1, tau.shape)
            * TORQUE_NOISE * effort, "exact": (q, qd, qdd)}


def sines(robot: hybrid.Robot, duration: float = 10.0) -> tuple[np.ndarray, ...]:
    """A sum of two sines per joint about the middle of its range (a motion the excitation never made)."""
    lo, hi = (np.asarray(x, float) for x in (robot.limits.lower, robot.limits.upper))
    mid, amp = (lo + hi) / 2, np.minimum(0.25 * (hi - lo), 1.0)
    t = np.arange(0.0, duration, 1.0 / RATE)[:, None]
    w = 2 * np.pi * np.linspace(0.15, 0.45, robot.n)
    q = mid + amp * (0.6 * np.sin(w * t) + 0.4 * np.sin(2.3 * w * t + 1.0))
    qd = amp * (0.6 * w * np.cos(w * t) + 0.4 * 2.3 * w * np.cos(2.3 * w * t + 1.0))
    qdd = -amp * (0.6 * w**2 * np.sin(w * t) + 0.4 * (2.3 * w) ** 2 * np.sin(2.3 * w * t + 1.0))
    return q, qd, qdd


def torque_errors(real, models: dict, motion) -> dict:
    """Per model, the RMS error of its predicted torques along ``motion``, per joint in % of the range there."""
    want = inverse_dynamics(real, *motion)
    span = want.max(axis=0) - want.min(axis=0)
    return {name: (100 * np.sqrt(np.mean((predict(*motion) - want) ** 2, axis=0)) / span).tolist()
            for name, predict in models.items()}


def closed_loop(make_experiment, real, models: dict) -> dict:
    """Per model told, the closed loop's RMS normal-force and speed errors and its normal force."""
    base = make_experiment(robot=real, force_reference=FORCE, speed_reference=hybrid.Step(*SPEEDS, STEP_AT),
                           duration=DURATION, sample_time=SAMPLE_TIME)
    out = {}
    for name, model in models.items():
        res = hybrid.simulate(dataclasses.replace(base, controller_robot=model))
        out[name] = {"rms_force_error_N": res.metrics["rms_force_error_N"],
                     "rms_speed_error_m_per_s": res.metrics["rms_speed_error_m_per_s"],
                     "t": res.t, "force_normal": res.force_normal}
    return out


def study_arm(name: str, quick: bool, seed: int = 0) -> dict:
    make_robot, make_experiment = ARMS[name]
    nominal = make_robot()
    real = real_arm(nominal, seed)
    rng = np.random.default_rng(seed + 100)
    t0 = time.perf_counter()
    traj = hybrid.excitation_trajectory(nominal, restarts=1 if quick else 3, seed=seed)
    excite_s = time.perf_counter() - t0
    data = log(traj, real, rng)
    t0 = time.perf_counter()
    found = hybrid.identify_dynamics(nominal, data["t"], data["q"], data["tau"])
    identify_s = time.perf_counter() - t0
    predictors = {"identified": found.torque,
                  "urdf": lambda q, qd, qdd: inverse_dynamics(nominal, q, qd, qdd)}
    other = hybrid.excitation_trajectory(nominal, period=7.0, restarts=1, seed=seed + 1)
    validation = {"another excitation": torque_errors(real, predictors, other.sample(np.arange(0, 7.0, 1 / RATE))),
                  "sines": torque_errors(real, predictors, sines(nominal))}
    loop = closed_loop(make_experiment, real, {"exact": real, "identified": found.robot, "urdf": nominal})
    return {"robot": name, "condition": traj.condition, "start_condition": traj.start_condition,
            "pseudo_inertias": [pseudo_inertia(link) for link in found.robot.links],
            "excitation_s": excite_s, "identification_s": identify_s, "samples": len(data["t"]),
            "base_parameters": len(found.names), "poorly_excited": list(found.poorly_excited),
            "validation": validation, "closed_loop": loop}


def table(results: list[dict]) -> str:
    lines = ["| arm | model told | RMS normal-force error [N] | RMS speed error [mm/s] | worst joint's torque "
             "error, held out [% of range] |", "|---|---|---|---|---|"]
    for r in results:
        for model, run in r["closed_loop"].items():
            held = [max(v[model]) for v in r["validation"].values() if model in v]
            worst = f"{max(held):.2f}" if held else "0 (the real arm)"
            lines.append(f"| {r['robot']} | {model} | {run['rms_force_error_N']:.4f} | "
                         f"{1e3 * run['rms_speed_error_m_per_s']:.2f} | {worst} |")
    return "\n".join(lines) + "\n"


def figure(results: list[dict], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, len(results), figsize=(5.5 * len(results), 6.5), squeeze=False)
    colours = {"exact": "k", "identified": "tab:blue", "urdf": "tab:red"}
    for col, r in enumerate(results):
        ax = axes[0, col]
        for model, run in r["closed_loop"].items():
            ax.plot(run["t"], run["force_normal"], color=colours[model], lw=1.0,
                    label=f"{model}: RMS error {run['rms_force_error_N']:.3f} N")
        ax.axhline(FORCE, color="0.6", lw=0.8, ls="--")
        ax.set(title=f"{r['robot']}: normal force, the controller told...", xlabel="t [s]", ylabel="N [N]")
        ax.legend(fontsize=8)
        ax = axes[1, col]
        errors = r["validation"]["sines"]
        x = np.arange(len(errors["urdf"]))
        for k, model in enumerate(("identified", "urdf")):
            ax.bar(x + 0.4 * k - 0.2, errors[model], width=0.4, color=colours[model], label=model)
        ax.set(yscale="log", title="held-out torques (sines): RMS error", xlabel="joint",
               ylabel="% of the joint's range")
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--quick", action="store_true", help="one restart of the excitation's optimisation")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    results = [study_arm(name, args.quick) for name in ARMS]
    figure(results, args.out / "identification.png")
    (args.out / "table.md").write_text(table(results))
    with open(args.out / "runs.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["arm", "model_told", "rms_force_error_N", "rms_speed_error_m_per_s"])
        for r in results:
            for model, run in r["closed_loop"].items():
                writer.writerow([r["robot"], model, run["rms_force_error_N"], run["rms_speed_error_m_per_s"]])
    for r in results:
        del r["pseudo_inertias"]
        for run in r["closed_loop"].values():
            del run["t"], run["force_normal"]
    (args.out / "study.json").write_text(json.dumps(results, indent=1))
    print(table(results))
    for r in results:
        print(f"{r['robot']}: condition {r['condition']:.1f} (start {r['start_condition']:.1f}), "
              f"{r['base_parameters']} base parameters, excitation {r['excitation_s']:.1f} s, identification "
              f"{r['identification_s']:.2f} s from {r['samples']} samples; poorly excited: {r['poorly_excited']}")
        for what, errors in r["validation"].items():
            print(f"  {what}: " + "; ".join(f"{m} {np.round(v, 3).tolist()}" for m, v in errors.items()))


if __name__ == "__main__":
    main()
