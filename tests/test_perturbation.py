"""``hybrid.perturbed_robot``: every link still a rigid body (its pseudo-inertia positive semidefinite, checked
here from its definition), each change within its share, the structure kept, the same seed the same robot."""

from __future__ import annotations

import numpy as np
import pytest

import hybrid


def pseudo_inertia(link) -> np.ndarray:
    """``[[Sigma, h], [h^T, m]]``: ``Sigma = int p p^T dm`` about the joint frame's origin, ``h = m c``."""
    m, c, Ic = link.mass, np.asarray(link.com), np.asarray(link.inertia)
    sigma_c = np.trace(Ic) / 2 * np.eye(3) - Ic
    return np.block([[sigma_c + m * np.outer(c, c), m * c[:, None]], [m * c[None, :], np.array([[m]])]])


@pytest.mark.parametrize("make", [hybrid.ur5, hybrid.panda])
@pytest.mark.parametrize("share", [0.0, 0.1, 0.3, 0.9])
def test_every_link_stays_a_rigid_body_within_its_share(make, share):
    robot = make()
    for seed in range(5):
        real = hybrid.perturbed_robot(robot, share, seed=seed)
        assert real.chain == robot.chain and real.damping == robot.damping and real.gravity == robot.gravity
        for a, b in zip(real.links, robot.links):
            if b.mass == 0:
                assert a == b
                continue
            assert np.linalg.eigvalsh(pseudo_inertia(a)).min() >= -1e-12 * np.abs(pseudo_inertia(a)).max()
            assert abs(a.mass / b.mass - 1) <= share + 1e-12
            Ia, Ib = np.linalg.eigvalsh(np.asarray(a.inertia)), np.linalg.eigvalsh(np.asarray(b.inertia))
            assert Ia.sum() <= (1 + share) * Ib.sum() * (1 + 1e-12)  # tr(I) = 2 sum(s): each s within its share
            assert Ia.sum() >= (1 - share) * Ib.sum() * (1 - 1e-12)
            gyration = np.sqrt(Ib.sum() / (2 * b.mass))
            assert np.abs(np.subtract(a.com, b.com)).max() <= share * gyration * (1 + 1e-12)
        if share == 0:  # the same robot, to the rounding of its inertias' eigen-decomposition
            np.testing.assert_allclose(real.as_array(), robot.as_array(), rtol=1e-12, atol=1e-15)
    assert hybrid.perturbed_robot(robot, share, seed=3) == hybrid.perturbed_robot(robot, share, seed=3)
    if share:
        assert hybrid.perturbed_robot(robot, share, seed=3) != hybrid.perturbed_robot(robot, share, seed=4)


def test_a_perturbed_robot_runs():
    real = hybrid.perturbed_robot(hybrid.ur5(), 0.3, seed=2)
    terms = hybrid.arm_terms(real, np.zeros(6) + 0.3, np.zeros(6))
    assert np.linalg.eigvalsh(terms["B"]).min() > 0


@pytest.mark.parametrize("share", [-0.1, 0.95, float("nan"), "0.3", True])
def test_a_share_out_of_range_is_refused(share):
    with pytest.raises(hybrid.HybridError, match="share"):
        hybrid.perturbed_robot(hybrid.ur5(), share)


@pytest.mark.parametrize("seed", [-1, 1.5, "a", None, True])
def test_a_seed_that_is_not_a_whole_number_is_refused(seed):
    """NumPy's generator would raise its own error, or (None) draw a robot no run repeats."""
    with pytest.raises(hybrid.HybridError, match=r"^seed = .*; give a whole number from 0"):
        hybrid.perturbed_robot(hybrid.ur5(), 0.3, seed=seed)


def test_the_planar_arm_is_refused():
    with pytest.raises(hybrid.HybridError, match="closed form"):
        hybrid.perturbed_robot(hybrid.Robot.planar(hybrid.paper_arm()), 0.1)
