"""The six task axes, named as the generated code names them.

The task frame's rows are ``t1, t2, n`` (linear axes 0-2), then the rotations about them (3-5):
``t1 = e x n / |e x n|`` for the reference direction ``e``, ``t2 = n x t1``, ``n`` the surface's
normal towards the robot.
"""

#: the six task axes, in the task frame's row order
AXIS_NAMES = ("t1", "t2", "n", "rot_t1", "rot_t2", "rot_n")
