"""examples/accelerometer.py: AngularKinematics then PointKinematics on the tumbling body. The
reading against the second difference of the sensor's position R(t) r in the fixed frame (R from
AngularKinematics at t and t +- h), rotated into the body: no cross product of ours in the check."""
import numpy as np

from conftest import ROOT
from examples import accelerometer
from examples.cross_check import simulate
from demo import trajectories

H = 1e-3


def rotation(times):
    theta, theta_dot, theta_ddot = trajectories.tumbling(times)
    names = [f"R[{i},{j}]" for i in (1, 2, 3) for j in (1, 2, 3)]
    _, y = simulate(str(ROOT / "dist" / "AngularKinematics.fmu"), "cs", times,
                    trajectories.INPUT_NAMES, np.hstack([theta, theta_dot, theta_ddot]), names)
    return y.reshape(-1, 3, 3)


def test_reading_is_the_acceleration_of_the_sensor_minus_gravity(tmp_path, report):
    times = np.linspace(0.5, 9.5, 10)
    result = accelerometer.accelerometer(ROOT / "dist", times)
    worst = 0.0
    for k, t in enumerate(times):
        R = rotation(np.array([t - H, t, t + H]))
        position = R @ accelerometer.LEVER_ARM  # fixed components, the centre at rest
        a_fixed = (position[2] - 2 * position[1] + position[0]) / H ** 2
        expected = R[1].T @ (a_fixed - accelerometer.G_FIXED)
        worst = max(worst, float(np.max(np.abs(result["specific_force"][k] - expected))))
    report(f"examples/accelerometer.py: reading within {worst:.2g} m/s2 of the second difference "
           f"(h = {H}) of R(t) r, minus g, at 10 instants")
    assert worst < 1e-4  # the difference's truncation error, O(h^2)


def test_the_example_writes_its_plot_and_table(tmp_path):
    assert accelerometer.main(["--stop", "1", "--out", str(tmp_path)]) == 0
    table = np.genfromtxt(tmp_path / "accelerometer.csv", delimiter=",", names=True)
    assert len(table) == 101 and (tmp_path / "accelerometer.png").stat().st_size > 10000
    at_rest = np.hypot(np.hypot(table["g_body1"], table["g_body2"]), table["g_body3"])
    assert np.allclose(at_rest, 9.81, rtol=1e-14)
