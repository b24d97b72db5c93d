"""The shipped Panda."""

from __future__ import annotations

from conftest import PANDA, UR5, example_robot

import hybrid
from hybrid.models.shipped import PANDA_URDF, UR5_URDF


def test_the_shipped_panda_is_example_robot_datas():
    assert PANDA_URDF.read_bytes() == example_robot(PANDA[0]).read_bytes()
    panda = hybrid.panda()
    assert panda.n == 7 and panda.joint_names == tuple(f"panda_joint{i}" for i in range(1, 8))
    assert panda == hybrid.Robot.from_urdf(example_robot(PANDA[0]), tip=PANDA[1])  # fingers off the chain: at 0
    assert hybrid.ur5() == hybrid.Robot.from_urdf(UR5_URDF, tip=UR5[1])


def test_the_shipped_urdfs_are_package_data():
    """Installed with the package (``hybrid.data``'s files), with their licences."""
    from importlib.resources import files

    data = files("hybrid.data")
    notice = (data / "NOTICE.md").read_text()
    for name in ("panda.urdf", "ur5_robot.urdf"):
        assert (data / name).is_file() and f"`{name}`" in notice
    assert "Apache License" in notice and "BSD 2-Clause License" in notice
