"""The demos: the tumbling body, the gimbal lock, and the trajectories they (and the tests) drive."""
