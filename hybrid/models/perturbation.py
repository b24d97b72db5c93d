"""A robot's inertial parameters perturbed at random, each link still a rigid body: a "real arm" for studies of
identification and of model error, whose parameters differ from its URDF's as real arms' do.

A link's inertia about its centre of mass ``I_c`` is that of a density whose second moments along its
principal axes are ``s_k = tr(I_c) / 2 - I_k >= 0`` (``I_k`` the principal moments): a rigid body's inertia
is exactly one with ``s_k >= 0`` (the triangle inequalities). Each link's mass is scaled by ``1 + u_m``, its
second moments by ``1 + u_k`` (so ``I_k = s_i + s_j`` stays a rigid body's), its principal axes
turned by a rotation of up to ``share`` rad about a random axis, and its centre of mass moved by up to
``share`` times the link's radius of gyration ``sqrt(tr(I_c) / 2m)`` in each coordinate; every ``u`` is
uniform in ``[-share, share]``. A massless link is kept as it is.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from hybrid.errors import HybridError
from hybrid.models.robot import Robot, as_robot
from hybrid.models.urdf import LinkInertia
from hybrid.validate import checked_keywords, shown, whole_number

#: the largest share accepted: beyond it a scaled mass or second moment may reach 0 or turn negative
MOST_SHARE = 0.9


def _turn(rng, angle: float) -> np.ndarray:
    """A rotation by ``angle`` about a random axis (Rodrigues' formula)."""
    k = rng.normal(size=3)
    k /= np.linalg.norm(k)
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def _perturbed_link(link: LinkInertia, share: float, rng) -> LinkInertia:
    if link.mass == 0:
        return link
    Ic = np.asarray(link.inertia, float)
    moments, axes = np.linalg.eigh(Ic)
    s = np.maximum(moments.sum() / 2 - moments, 0.0)  # second moments of the density along the principal axes
    u_m, u = rng.uniform(-share, share), rng.uniform(-share, share, 3)
    s = s * (1 + u)
    axes = _turn(rng, rng.uniform(-share, share)) @ axes
    I_new = axes @ np.diag(s.sum() - s) @ axes.T
    gyration = math.sqrt(max(moments.sum(), 0.0) / (2 * link.mass))
    com = np.asarray(link.com, float) + rng.uniform(-share, share, 3) * gyration
    I_new = (I_new + I_new.T) / 2
    return LinkInertia(link.mass * (1 + u_m), tuple(map(float, com)), tuple(map(tuple, I_new.tolist())))


@checked_keywords
def perturbed_robot(robot: Robot, share: float = 0.3, *, seed: int = 0) -> Robot:
    """``robot`` with each link's mass, centre of mass and inertia perturbed at random by up to ``share``, each
    still a rigid body's (module docstring); its structure, friction, gravity and limits kept.

    Parameters
    ----------
    robot : Robot
        A serial-chain robot (the planar arm's closed form has parameters of its own: scale its ``Arm``).
    share : float
        The largest relative change of a mass and of a second moment, the largest turn of the principal
        axes [rad], and the largest shift of the centre of mass in radii of gyration; in ``[0, 0.9]``.
    seed : int
        The random generator's seed: the same seed gives the same robot.

    Returns
    -------
    Robot
        The perturbed robot.

    Raises
    ------
    HybridError
        ``share`` outside ``[0, 0.9]``, a seed that is not a whole number >= 0, or the planar arm.

    Examples
    --------
    >>> import numpy as np
    >>> import hybrid
    >>> ur5 = hybrid.ur5()
    >>> real = hybrid.perturbed_robot(ur5, 0.3, seed=1)
    >>> ratio = np.array([a.mass / b.mass
    ...                   for a, b in zip(real.links, ur5.links)])
    >>> within = np.all((ratio >= 0.7) & (ratio <= 1.3))
    >>> bool(within), real.chain == ur5.chain
    (True, True)
    """
    robot = as_robot(robot)
    if isinstance(share, bool) or not isinstance(share, (int, float, np.integer, np.floating)) \
            or not 0 <= share <= MOST_SHARE:
        raise HybridError(f"share = {shown(share, 40)}; give the largest relative change, a number in [0, "
                          f"{MOST_SHARE}] (0.3 for up to 30 %)")
    if robot.closed_form is not None:
        raise HybridError("the planar arm's parameters are its closed form's: perturb its hybrid.Arm "
                          "(dataclasses.replace(arm, m2=...)) and build Robot.planar from it")
    rng = np.random.default_rng(whole_number("seed", seed, 0, 2**63 - 1))
    links = tuple(_perturbed_link(link, float(share), rng) for link in robot.links)
    return dataclasses.replace(robot, links=links)
