"""Smooth orientation histories theta(t) of a tumbling body, with their exact first and second
time derivatives, as fmpy input signals."""
import numpy as np

INPUT_NAMES = [f"{base}[{i}]" for base in ("theta", "theta_dot", "theta_ddot") for i in (1, 2, 3)]

# theta_i(t) = rate_i t + amplitude_i sin(frequency_i t + phase_i). theta2 swings to within
# 0.05 rad of +-pi/2, where the body-fixed 1-2-3 description is nearly singular.
RATE = np.array([0.6, 0.0, 2.5])
AMPLITUDE = np.array([0.8, np.pi / 2 - 0.05, 0.5])
FREQUENCY = np.array([1.3, 0.9, 2.1])
PHASE = np.array([0.0, 0.4, 1.0])


def sinusoidal(times, rate, amplitude, frequency, phase):
    """(theta, theta_dot, theta_ddot), each len(times) x 3, of
    theta_i(t) = rate_i t + amplitude_i sin(frequency_i t + phase_i)."""
    t = np.asarray(times, dtype=float)[:, None]
    argument = frequency * t + phase
    theta = rate * t + amplitude * np.sin(argument)
    theta_dot = rate + amplitude * frequency * np.cos(argument)
    theta_ddot = -amplitude * frequency ** 2 * np.sin(argument)
    return theta, theta_dot, theta_ddot


def tumbling(times):
    """(theta, theta_dot, theta_ddot) of the demonstration's tumbling body."""
    return sinusoidal(times, RATE, AMPLITUDE, FREQUENCY, PHASE)


def as_input_signals(times, theta, theta_dot, theta_ddot):
    """A structured array with 'time' and the nine inputs, as simulate_fmu takes it."""
    columns = np.hstack([theta, theta_dot, theta_ddot])
    signals = np.zeros(len(times), dtype=[("time", float)] + [(name, float) for name in INPUT_NAMES])
    signals["time"] = times
    for k, name in enumerate(INPUT_NAMES):
        signals[name] = columns[:, k]
    return signals


def input_signals(times):
    """The demonstration's inputs as simulate_fmu takes them."""
    return as_input_signals(times, *tumbling(times))
