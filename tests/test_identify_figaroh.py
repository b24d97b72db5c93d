"""The base parameters identified from joint torques, beside FIGAROH's identification on the same data.

FIGAROH (``pip install figaroh``) is an open toolbox for dynamics identification on Pinocchio. Its own
steps are used, as its ``BaseIdentification.solve`` chains them: the stacked regressor
(``tools.regressor.build_regressor_basic``: Pinocchio's ``computeJointTorqueRegressor`` per sample, rows
joint by joint, viscous ``fv`` and Coulomb ``fs`` friction columns, a torque offset ``off`` per joint
where the library's regressor has one), its standard parameters
(``identification.parameter``), the columns without effect dropped (``get_index_eliminate``) and the
base parameters and their least-squares estimate by its double QR
(``tools.qrdecomposition.QRDecomposer.double_decomposition``), both tolerances as ``solve`` sets them. The
``BaseIdentification`` class itself is not used: it wants a YAML file, a subclass that loads the data
and sets the active joints, and low-pass filters the given positions, velocities and accelerations.

The same data for both: the UR5 and the Panda (Pinocchio's models of the shipped URDFs, the Panda's
fingers locked) with every link's mass, centre of mass and principal second moments changed by up to
30 % and its principal axes turned (each link a rigid body still), a viscosity on every joint; a
multi-sine excitation of 6 s at 1 kHz; the torques Pinocchio's RNEA of the changed model plus the
viscous torques, with Gaussian noise of 1 % of each joint's torque range; a held-out multi-sine of 3 s.

What was measured (seeds as below, one run on 2 shared cores):

- base parameters: 54 for the UR5 in both (36 inertial; a viscosity, a Coulomb friction and an offset per
  joint), 64 for the Panda (43 and 3 x 7). The inertial base columns of the two span the same space, of the
  rank of Pinocchio's stacked regressor. The base regressor's condition number: 1391 (both) on the UR5, 678
  (ours) and 692 (FIGAROH) on the Panda.
- noise-free: both give the held-out torques to 1e-13 of each joint's range or better and the true base
  parameters, each in its own choice of them, to 5e-14 relative.
- with noise, ordinary least squares (FIGAROH's default): the held-out torque error against the noise-free
  truth is 0.03-0.25 % of each joint's range for both on the UR5, 0.05-1.7 % on the Panda (the largest at
  its last joint, whose torque range is 1/200 of the second's: the large joints' noise sets the parameters
  it depends on); FIGAROH's error is 0.93-1.07 times ours: the same method on the same columns.
- with noise, the library's default (each joint weighted by its noise, estimated from the unweighted fit's
  residual): 0.02-0.08 % on the UR5 and 0.03-0.09 % on the Panda; the wrists 3-7 times better than
  ordinary least squares on the UR5, the Panda's last three joints 6-40 times. FIGAROH offers the same
  (``solve(wls=True)``); its default does not weight.
- the choice of base parameters: ours keeps a parameter unless it is a combination of those before it
  in ``pi`` (m, m c, I_O per link, base to tip; the choice depends on the structure only); FIGAROH
  keeps the columns of largest remaining norm on the trajectory's own regressor (ties by name), so its
  choice and rank follow the data: a trajectory that leaves the UR5's last joint still gave it 46 base
  parameters and a fit without complaint (its held-out torque at that joint then 23 % of the range
  off), where ours refuses naming the parameter not excited (measured apart). The
  sets differ in a few parameters (UR5: ours ``IOzz[wrist_2]`` for FIGAROH's ``Izz_wrist_3``; Panda:
  7 of 43).
- time for 6000 samples, best of three (measured apart, before the friction columns): ours 0.08-0.15 s in
  all; FIGAROH 0.4-0.7 s (its regressor in a Python loop over samples and joints, its double QR three QR
  factorisations of the stacked regressor).
"""

from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np
import pytest
from conftest import pinocchio_model

import hybrid
from hybrid.models.shipped import PANDA_URDF, UR5_URDF

pin = pytest.importorskip("pinocchio")
figaroh_regressor = pytest.importorskip("figaroh.tools.regressor")
figaroh_qr = pytest.importorskip("figaroh.tools.qrdecomposition")
figaroh_parameter = pytest.importorskip("figaroh.identification.parameter")

RATE = 1000.0  # Hz
#: FIGAROH's BaseIdentification.solve: the squared column norm below which a column is dropped, and
#: the rank tolerance of its QR
FIGAROH_ZERO_TOLERANCE, FIGAROH_QR_TOLERANCE = 1e-3, 1e-6
NOISE = 0.01  # of each joint's torque range


def multisine(rng, lower, upper, duration: float, *, harmonics: int = 5, speed: float = 1.5,
              acceleration: float = 8.0):
    """A sum of sines per joint at ``1 / duration`` Hz and its harmonics (one period: smooth, exact
    derivatives), about the middle of each joint's range, scaled to stay within 80 % of its half range
    (at most pi) and under ``speed`` [rad/s] and ``acceleration`` [rad/s^2]: ``t, q, q', q''``."""
    t = np.arange(round(duration * RATE)) / RATE
    w = 2 * np.pi / duration * np.arange(1, harmonics + 1)
    a, b = rng.normal(0, 1, (2, len(lower), harmonics)) / np.arange(1, harmonics + 1)
    s, c = np.sin(np.outer(t, w)), np.cos(np.outer(t, w))
    q, qd, qdd = s @ a.T + c @ b.T, (c * w) @ a.T - (s * w) @ b.T, -(s * w**2) @ a.T - (c * w**2) @ b.T
    half = np.minimum((upper - lower) / 2, np.pi)
    scale = np.min([0.8 * half / np.abs(q).max(0), speed / np.abs(qd).max(0),
                    acceleration / np.abs(qdd).max(0)], axis=0)
    return t, (upper + lower) / 2 + scale * q, scale * qd, scale * qdd


def perturbed(rng, model, robot, share: float = 0.3):
    """Pinocchio's ``model`` and ``robot`` with every link changed alike: the mass and each coordinate of
    the centre of mass by up to ``share`` (and 1 cm), the principal second moments of mass about the
    centre of mass (``tr(I_c)/2 - I_c``, positive semi-definite for a rigid body) each by up to ``share``
    and their axes turned by up to ``share`` rad about each axis; and a viscosity on every joint."""
    true = model.copy()
    viscosity = robot.limits.effort * rng.uniform(0.002, 0.02, robot.n)  # N m s/rad
    for i, joint in enumerate(robot.joint_names):
        body = model.inertias[i + 1]
        mass = body.mass * rng.uniform(1 - share, 1 + share)
        com = body.lever * rng.uniform(1 - share, 1 + share, 3) + rng.uniform(-0.01, 0.01, 3)
        second, axes = np.linalg.eigh(0.5 * np.trace(body.inertia) * np.eye(3) - body.inertia)
        axes = pin.exp3(rng.uniform(-share, share, 3)) @ axes
        second = axes @ np.diag(second * rng.uniform(1 - share, 1 + share, 3)) @ axes.T
        inertia = np.trace(second) * np.eye(3) - second
        true.inertias[i + 1] = pin.Inertia(mass, com, inertia)
        robot = robot.with_link(joint, mass=mass, com=com, inertia=inertia, damping=viscosity[i])
    return true, robot, viscosity


def rnea(model, viscosity, q, qd, qdd) -> np.ndarray:
    """Pinocchio's inverse dynamics of N states plus the viscous torques (the independent truth)."""
    data = model.createData()
    return np.array([pin.rnea(model, data, *x) for x in zip(q, qd, qdd)]) + viscosity * qd


def identify_ours(robot, t, q, qd, qdd, tau, weighted: bool = False):
    """The library's identification of ``robot`` from samples at times ``t`` (the one call to it): ordinary
    least squares as FIGAROH's default, or (``weighted``) the library's own default, weighted."""
    return hybrid.identify_dynamics(robot, t, q, tau, qd=qd, qdd=qdd, smooth=False, weighted=weighted,
                                    consistent=False)


@dataclass
class FigarohFit:
    """FIGAROH's identification: its columns kept, base columns, estimate and conditioning."""

    model: object
    config: dict
    eliminated: list
    params_r: list
    names: list
    base_indices: list
    estimate: np.ndarray
    M: np.ndarray
    condition: float

    def regressor(self, q, qd, qdd) -> np.ndarray:
        """FIGAROH's stacked regressor of N states (rows joint by joint), its kept columns."""
        robot = SimpleNamespace(model=self.model, data=self.model.createData())
        W = figaroh_regressor.build_regressor_basic(robot, q, qd, qdd, self.config)
        return figaroh_regressor.build_regressor_reduced(W, self.eliminated)

    def torque(self, q, qd, qdd) -> np.ndarray:
        """``(N, n)`` torques of the identified base parameters."""
        W = self.regressor(q, qd, qdd)[:, self.base_indices]
        return (W @ self.estimate).reshape(self.model.nv, len(q)).T

    def true_base(self, model, viscosity) -> np.ndarray:
        """FIGAROH's base parameters of the arm ``model`` with joint viscosities ``viscosity``."""
        theta = figaroh_parameter.get_standard_parameters(model, self.config)
        config = {**self.config, "fv": list(viscosity)}
        theta.update(figaroh_parameter.add_standard_additional_parameters(model, config))
        return self.M @ np.array([theta[name] for name in self.params_r])


def identify_figaroh(model, q, qd, qdd, tau, *, offset: bool) -> FigarohFit:
    """FIGAROH's base parameters of Pinocchio's ``model`` from N samples, by its own steps: links'
    inertial parameters, viscous and Coulomb friction (FIGAROH's come together) and, if ``offset``, a
    constant torque offset per joint (nominally all 0)."""
    n = model.nv
    config = {"act_idxv": list(range(n)), "has_friction": True, "has_actuator_inertia": False,
              "has_joint_offset": offset, "is_joint_torques": True, "is_external_wrench": False,
              "fv": [0.0] * n, "fs": [0.0] * n, "off": [0.0] * n}
    robot = SimpleNamespace(model=model, data=model.createData())
    W = figaroh_regressor.build_regressor_basic(robot, q, qd, qdd, config)
    standard = figaroh_parameter.get_standard_parameters(model, config)
    standard.update(figaroh_parameter.add_standard_additional_parameters(model, config))
    eliminated, params_r = figaroh_regressor.get_index_eliminate(W, standard, tol_e=FIGAROH_ZERO_TOLERANCE)
    W_e = figaroh_regressor.build_regressor_reduced(W, eliminated)
    decomposer = figaroh_qr.QRDecomposer(tolerance=FIGAROH_QR_TOLERANCE)
    _, _, names, estimate = decomposer.double_decomposition(tau.T.ravel(), W_e, params_r)  # rows joint by joint
    return FigarohFit(model, config, eliminated, params_r, names, decomposer.get_base_indices(), estimate,
                      decomposer.get_M(), decomposer.get_diagnostics()["cond_R1"])


@pytest.fixture(scope="module", params=["ur5", "panda"])
def case(request):
    """One arm's data and both tools' fits to it, noise-free and noisy."""
    robot, urdf, seed = {"ur5": (hybrid.ur5(), UR5_URDF, 11), "panda": (hybrid.panda(), PANDA_URDF, 12)}[request.param]
    rng = np.random.default_rng(seed)
    model = pinocchio_model(urdf, robot.joint_names)
    assert tuple(model.names[1:]) == robot.joint_names
    true, true_robot, viscosity = perturbed(rng, model, robot)
    lower, upper = robot.limits.lower, robot.limits.upper
    train, held = multisine(rng, lower, upper, 6.0), multisine(rng, lower, upper, 3.0)
    tau, tau_held = rnea(true, viscosity, *train[1:]), rnea(true, viscosity, *held[1:])
    sigma = NOISE * np.ptp(tau, axis=0)
    noisy = tau + rng.normal(0, 1, tau.shape) * sigma
    out = SimpleNamespace(robot=robot, model=model, true=true, true_robot=true_robot, viscosity=viscosity,
                          held=held, tau_held=tau_held)
    # FIGAROH fits a torque offset per joint where the library's regressor has one: the same friction model
    offset = any(name.startswith("offset[") for name in hybrid.regressor(robot, *(x[0] for x in train[1:]))[1])
    for key, torques in (("exact", tau), ("noisy", noisy)):
        fits = SimpleNamespace(ours=identify_ours(robot, *train, torques),
                               weighted=identify_ours(robot, *train, torques, weighted=True),
                               figaroh=identify_figaroh(model, *train[1:], torques, offset=offset))
        setattr(out, key, fits)
    return out


def _rms(a) -> np.ndarray:
    return np.sqrt((np.asarray(a) ** 2).mean(axis=0))


def _inertial_or_viscous(names, figaroh: bool) -> list[int]:
    """The base parameters that are links' inertial ones or joint viscosities (not Coulomb friction
    or a torque offset, which the truth has none of)."""
    other = ("fs_", "off_") if figaroh else ("coulomb[", "offset[")
    return [k for k, name in enumerate(names) if not name.startswith(other)]


def test_the_same_base_parameters(case):
    """As many inertial base parameters in both, a viscosity per joint in both, a Coulomb friction per
    joint in FIGAROH's; the inertial and viscous base columns of the two span the same space at other
    states, of the rank of Pinocchio's regressor stacked there plus a viscosity per joint."""
    n, ours, fig = case.robot.n, case.exact.ours, case.exact.figaroh
    viscous = {"ours": [k for k, name in enumerate(ours.names) if name.startswith("damping[")],
               "figaroh": [k for k, name in enumerate(fig.names) if name.startswith("fv_")]}
    assert len(viscous["ours"]) == len(viscous["figaroh"]) == n
    assert sum(name.startswith("fs_") for name in fig.names) == n
    keep = {"ours": _inertial_or_viscous(ours.names, False), "figaroh": _inertial_or_viscous(fig.names, True)}
    assert len(keep["ours"]) == len(keep["figaroh"])
    q, qd, qdd = (x[::20] for x in case.held[1:])
    Y, _ = hybrid.regressor(case.robot, q, qd, qdd)
    W_ours = ours.base.regressor(Y).transpose(1, 0, 2).reshape(len(q) * n, -1)[:, keep["ours"]]  # joint by joint
    W_fig = fig.regressor(q, qd, qdd)[:, fig.base_indices][:, keep["figaroh"]]
    rank = np.linalg.matrix_rank
    assert rank(W_ours) == rank(W_fig) == rank(np.hstack([W_ours, W_fig])) == len(keep["ours"])
    data = case.model.createData()
    W_pin = np.vstack([pin.computeJointTorqueRegressor(case.model, data, *x) for x in zip(q, qd, qdd)])
    assert rank(W_pin) + n == len(keep["ours"])


def test_noise_free_both_give_the_torques_and_the_true_base_parameters(case):
    """Exact torques: both predict the held-out torques to rounding (1e-9 of each joint's range) and
    give the true base parameters, each in its own choice of them, to 1e-7 relative (FIGAROH's Coulomb
    friction 0): the FIGAROH steps are set up right."""
    ours, fig = case.exact.ours, case.exact.figaroh
    span = np.ptp(case.tau_held, axis=0)
    for tool in (ours, fig):
        assert (_rms(tool.torque(*case.held[1:]) - case.tau_held) < 1e-9 * span).all()
    want = hybrid.base_parameters(case.robot).of(hybrid.linear_parameters(case.true_robot))
    assert np.abs(ours.estimate - want).max() < 1e-7 * np.abs(want).max()
    want = fig.true_base(case.true, case.viscosity)
    assert np.abs(fig.estimate - want).max() < 1e-7 * np.abs(want).max()


def test_noisy_the_two_agree(case):
    """Noise of 1 % of each joint's torque range: on the held-out trajectory each tool's torque error
    against the noise-free truth is under 3 % of the range for every joint (a wrong fit is tens of
    percent), the two within a factor 2 of each other and their predictions closer to each other than
    the larger error; both tools' viscosities are within 15 % of the truth."""
    ours, fig = case.noisy.ours, case.noisy.figaroh
    span = np.ptp(case.tau_held, axis=0)
    predicted = {"ours": ours.torque(*case.held[1:]), "figaroh": fig.torque(*case.held[1:])}
    error = {key: _rms(tau - case.tau_held) for key, tau in predicted.items()}
    for key in error:
        assert (error[key] < 0.03 * span).all(), (key, error[key] / span)
    ratio = error["figaroh"] / error["ours"]
    assert ((1 / 2 < ratio) & (ratio < 2)).all(), ratio
    assert (_rms(predicted["ours"] - predicted["figaroh"]) < np.maximum(error["ours"], error["figaroh"])).all()
    ours_viscosity = ours.estimate[[ours.names.index(f"damping[{j}]") for j in case.robot.joint_names]]
    fig_viscosity = fig.estimate[[fig.names.index(f"fv_{j}") for j in case.robot.joint_names]]
    for found in (ours_viscosity, fig_viscosity):
        np.testing.assert_allclose(found, case.viscosity, rtol=0.15)


def test_weighted_the_small_joints_come_out_better(case):
    """The library's default, each joint weighted by its noise: no joint's held-out error more than 25 % above
    ordinary least squares', and the worst-served joints (the wrists, whose torques are a tenth of the
    shoulders' and their noise with them) several times better (measured: up to 7 times)."""
    span = np.ptp(case.tau_held, axis=0)
    error = {key: _rms(getattr(case.noisy, key).torque(*case.held[1:]) - case.tau_held) for key in ("ours", "weighted")}
    assert (error["weighted"] < 0.03 * span).all()
    assert (error["weighted"] <= 1.25 * error["ours"]).all(), error["weighted"] / error["ours"]
    assert (error["ours"] / error["weighted"]).max() > 2.0
