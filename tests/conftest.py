"""Random arms, surfaces and states shared by the tests (seeded: failures reproduce)."""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, distribution
from pathlib import Path

import numpy as np
import pytest

import hybrid


def random_arm(rng: np.random.Generator, gravity: bool | None = None) -> hybrid.Arm:
    """A physically valid two-link arm with every parameter drawn at random."""
    L1, L2 = rng.uniform(0.2, 1.0, 2)
    g = (9.81 if rng.random() < 0.5 else 0.0) if gravity is None else (9.81 if gravity else 0.0)
    return hybrid.Arm(L1=L1, L2=L2, m1=rng.uniform(0, 5), m2=rng.uniform(0.5, 5),
                      d1=rng.uniform(0, L1), d2=rng.uniform(0, L2), I1=rng.uniform(0.01, 0.5),
                      I2=rng.uniform(0.01, 0.5), V1=rng.uniform(0, 2), V2=rng.uniform(0, 2), gravity=g)


def random_surface(rng: np.random.Generator, kind: str):
    if kind == "circle":
        return hybrid.Circle(center=rng.uniform(-1, 1, 2), radius=rng.uniform(0.05, 0.5))
    return hybrid.Plane(point=rng.uniform(-1, 1, 2), normal=rng.normal(size=2))


def random_states(rng: np.random.Generator, n: int, elbow: int = 1) -> dict[str, np.ndarray]:
    """``n`` non-singular states (|sin q2| >= sin 0.2) with the given elbow sign."""
    q = np.column_stack([rng.uniform(-np.pi, np.pi, n), elbow * rng.uniform(0.2, np.pi - 0.2, n)])
    return {"q": q, "qdot": rng.normal(0, 2, (n, 2)), "a": rng.normal(0, 3, (n, 2)),
            "Fc": rng.normal(0, 10, (n, 2))}


@pytest.fixture
def rng():
    return np.random.default_rng(20261122)


def example_robot(relative: str) -> Path:
    """A URDF shipped by the ``example-robot-data`` package (files nobody here wrote)."""
    try:
        dist = distribution("example-robot-data")
    except PackageNotFoundError:
        pytest.skip("example-robot-data is not installed (pip install example-robot-data)")
    for f in dist.files or ():
        if str(f).endswith(relative):
            return Path(dist.locate_file(f))
    pytest.skip(f"example-robot-data has no {relative}")


UR5 = ("ur_description/urdf/ur5_robot.urdf", "tool0")
PANDA = ("panda_description/urdf/panda.urdf", "panda_hand_tcp")


def pinocchio_model(urdf, joint_names):
    """Pinocchio's model of a URDF with only ``joint_names`` moving, the others locked at their neutral
    position (0, where :meth:`hybrid.Robot.from_urdf` holds them)."""
    pin = pytest.importorskip("pinocchio")
    model = pin.buildModelFromUrdf(str(urdf))
    extra = [model.getJointId(name) for name in model.names[1:] if name not in joint_names]
    return pin.buildReducedModel(model, extra, pin.neutral(model)) if extra else model


@pytest.fixture(scope="module")
def robots():
    """The UR5 and the Panda of example-robot-data, viscosity on every joint, with Pinocchio's models."""
    out = {}
    for key, (path, tip) in {"ur5": UR5, "panda": PANDA}.items():
        urdf = example_robot(path)
        robot = hybrid.Robot.from_urdf(urdf, tip=tip)
        robot = hybrid.Robot(robot.name, robot.chain, robot.links, tuple(np.linspace(0.1, 0.6, robot.n)),
                             robot.gravity, robot.limits)  # viscosity on every joint
        model = pinocchio_model(urdf, robot.joint_names)
        out[key] = (robot, model, model.getFrameId(tip))
    return out


def pinocchio_terms(model, fid, q, qd, damping):
    """J, J' q', B, n and the tip position from Pinocchio (the oracle's inputs)."""
    import pinocchio as pin

    data = model.createData()
    pin.forwardKinematics(model, data, q, qd, np.zeros_like(q))
    pin.updateFramePlacements(model, data)
    B = pin.crba(model, data, q)
    return (pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL_WORLD_ALIGNED),
            pin.getFrameClassicalAcceleration(model, data, fid, pin.LOCAL_WORLD_ALIGNED).vector.copy(),
            np.triu(B) + np.triu(B, 1).T, pin.nonLinearEffects(model, data, q, qd) + damping * qd,
            data.oMf[fid].translation.copy())


def well_conditioned_states(rng, robot, model, fid, surface, N, e=(0.0, 0.0, 1.0)):
    """Random states with a well-conditioned J and a defined task frame (and their Pinocchio terms)."""
    from hybrid import oracle

    out = []
    while len(out) < N:
        q = rng.uniform(robot.limits.lower, robot.limits.upper)
        qd = rng.normal(0, 1, robot.n)
        terms = pinocchio_terms(model, fid, q, qd, np.array(robot.damping))
        s = np.linalg.svd(terms[0], compute_uv=False)
        R, _ = oracle.spatial_frame(surface, terms[4], terms[0][:3] @ qd, e)
        if s[-1] / s[0] > 0.05 and np.isfinite(R).all() and np.linalg.norm(np.cross(e, R[2])) > 0.1:
            out.append((q, qd, terms))
    return out


def blockdiag(R):
    """``diag(R, R)``: a 3 x 3 rotation acting on a twist's linear and angular parts."""
    Z3 = np.zeros((3, 3))
    return np.block([[R, Z3], [Z3, R]])


def pinocchio_panda():
    """Pinocchio's Panda from the shipped URDF, the fingers locked at 0 as :func:`hybrid.panda` does."""
    from hybrid.models.shipped import PANDA_URDF

    pin = pytest.importorskip("pinocchio")
    model = pinocchio_model(PANDA_URDF, hybrid.panda().joint_names)
    return pin, model, model.createData(), model.getFrameId(PANDA[1])


def task_acceleration_gap(panda, exp, ctrl, q, qdot, Fc, tau):
    """How far the task acceleration ``R v' + R' v`` of Pinocchio's arm under the torque ``tau`` and the
    sensor's force ``Fc`` is from the loops' ``a`` of the controller's latest sample, and ``J``."""
    from hybrid import oracle

    pin, model, data, fid = panda
    pin.forwardKinematics(model, data, q, qdot, np.zeros(len(q)))
    pin.updateFramePlacements(model, data)
    J = pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL_WORLD_ALIGNED)
    Jdqd = pin.getFrameClassicalAcceleration(model, data, fid, pin.LOCAL_WORLD_ALIGNED).vector
    qdd = pin.aba(model, data, q, qdot, tau + J[:3].T @ Fc[:3] - np.array(exp.robot.damping) * qdot)
    v, vdot = J @ qdot, J @ qdd + Jdqd
    R, Rd = oracle.spatial_frame(exp.surface, data.oMf[fid].translation.copy(), v[:3], exp.frame_direction)
    return np.abs(blockdiag(R) @ vdot + blockdiag(Rd) @ v - ctrl.last["a"]).max(), J
