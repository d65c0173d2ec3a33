"""AttitudePropagator: the one description of this model (see AngularKinematics/description.py for
the rules: value references are forever, arrays take consecutive ones, `depends` per element).

The first model with continuous states: `state=True` marks q (its start comes from the parameters
named by `initial_depends`), `derivative_of` marks der(q), a local variable. `depends` may name
states as well as inputs: <Outputs> and <Derivatives> list both; <InitialUnknowns> lists the
inputs and, in place of each state, the parameters its start is computed from."""

NAME = "AttitudePropagator"
C_PREFIX = "AP"  # of the generated C names: AP_VR_..., AP_VARIABLES
GUID = "{8b5e2f4a-7c13-4d9e-b0a6-51e3c9d2f7a8}"
DESCRIPTION = ("Attitude of a rotating rigid body integrated on unit quaternions from its angular "
               "velocity (body or fixed components), never meeting a singularity; rotation "
               "matrix, angles of any of the 24 rotation sequences, their rates and the angular "
               "velocity and acceleration in both frames as outputs")
SOURCES = ["model.c"]
# The core's sources this model calls (relative to fmu_src/): its FMU compiles and ships these
# alone, with the headers they and the model include (tests/python/test_dead_code.py).
CORE = ["core/sequences.c", "core/kinematics_general.c", "core/kinematics_partials.c",
        "core/kinematics_euler_rates.c", "core/kinematics_rates_sequences.c", "core/attitude.c",
        "core/attitude_angles.c",
        "elementary/elementary_reduce.c", "elementary/elementary_atan2.c"]
# The FMU's documentation/index.html (codegen/documentation.py): these pages or their sections.
DOCUMENTATION = [("docs/attitude_propagator.md", None),
                 ("docs/cosimulation.md", ["The reference result each FMU carries (FMI-LS-REF)"])]
CAPABILITIES = dict(provides_directional_derivative=True, can_interpolate_inputs=True,
                    max_output_derivative_order=0)
ENUMERATIONS = {
    "Frame": dict(description="frame of the components of omega and omega_dot",
                  items=[("fixed", "components along the fixed axes n1, n2, n3"),
                         ("body", "components along the body axes b1, b2, b3")]),
}


def _other_q(k):
    """der(q[k]) = (q (x) (0, omega))[k] / 2 has no q[k] term, in either frame."""
    return [f"q[{m}]" for m in (1, 2, 3, 4) if m != k] + ["omega"]


# The outputs of the cross-check results (scripts/make_cross_check.py; at most 10).
CROSS_CHECK_OUTPUTS = ([f"q[{i}]" for i in (1, 2, 3, 4)] +
                       [f"{n}[{i}]" for n in ("theta", "theta_dot") for i in (1, 2, 3)])

VARIABLES = [
    dict(name="omega", vr=0, shape=(3,), causality="input", type="AngularVelocity",
         description="component {i} of the angular velocity of the body, in the frame of "
                     "parameter frame"),
    dict(name="omega_dot", vr=3, shape=(3,), causality="input", type="AngularAcceleration",
         description="time derivative of omega[{i}]; optional: all three zero means not given "
                     "(co-simulation then uses the input derivatives of omega, if any)"),
    dict(name="q", vr=6, shape=(4,), causality="output", type="Dimensionless", state=True,
         initial_depends=["q0"],
         description="unit quaternion of the attitude, component {i} (scalar first, Hamilton "
                     "product; continuous in time, its sign is not normalized); continuous state",
         depends=lambda i: [f"q[{i}]"]),
    # group lazy: a get computes it (model exchange's fmi2GetDerivatives computes it itself).
    dict(name="der(q)", vr=10, shape=(4,), causality="local", type="Frequency", group="lazy",
         derivative_of="q", description="time derivative of q[{i}]", depends=_other_q),
    dict(name="R", vr=14, shape=(3, 3), causality="output", type="Dimensionless",
         description="direction cosine matrix, row {i} column {j}: v_fixed = R v_body",
         depends=["q"]),
    dict(name="theta", vr=23, shape=(3,), causality="output", type="Angle",
         description="angle {i} of the rotation sequence (parameter sequence), continuous in "
                     "time (unwrapped; see the documentation for the singular configuration)",
         depends=["q"]),
    dict(name="theta_dot", vr=26, shape=(3,), causality="output", type="AngularVelocity",
         group="lazy", description="first time derivative of theta[{i}]",
         depends=["q", "omega"]),
    dict(name="omega_fixed", vr=29, shape=(3,), causality="output", type="AngularVelocity",
         group="lazy",
         description="fixed-frame component {i} of the angular velocity of the body",
         depends=["q", "omega"]),
    dict(name="omega_body", vr=32, shape=(3,), causality="output", type="AngularVelocity",
         group="lazy",
         description="body-frame component {i} of the angular velocity of the body",
         depends=["q", "omega"]),
    dict(name="alpha_fixed", vr=35, shape=(3,), causality="output", type="AngularAcceleration",
         group="lazy",
         description="fixed-frame component {i} of the angular acceleration of the body "
                     "(omega_dot, or the input derivative of omega when omega_dot is zero)",
         depends=["q", "omega_dot"]),
    dict(name="alpha_body", vr=38, shape=(3,), causality="output", type="AngularAcceleration",
         group="lazy",
         description="body-frame component {i} of the angular acceleration of the body "
                     "(omega_dot, or the input derivative of omega when omega_dot is zero)",
         depends=["q", "omega_dot"]),
    dict(name="singularity_distance", vr=41, causality="output", type="Dimensionless",
         description="|det W| of parameter sequence at the attitude: |cos theta[2]| (Tait-Bryan) "
                     "or |sin theta[2]| (proper Euler); for the angle outputs only, the "
                     "integration never depends on it",
         depends=["q"]),
    dict(name="frame", vr=42, causality="parameter", type="Frame", start="body",
         description="frame of the components of the inputs omega and omega_dot"),
    dict(name="sequence", vr=43, causality="parameter", type="Sequence", start="body123",
         description="rotation sequence of the angle outputs theta"),
    # Co-simulation memory of the step (core/attitude.h, section 4): values, so that an FMU state
    # carries them and a replay is bit-identical.
    dict(name="omega_previous", vr=48, shape=(3,), causality="local", type="AngularVelocity",
         description="co-simulation: omega[{i}] at the previous communication point",
         depends=[]),
    dict(name="omega_dot_previous", vr=51, shape=(3,), causality="local",
         type="AngularAcceleration",
         description="co-simulation: the time derivative of omega[{i}] used at the previous "
                     "communication point", depends=[]),
    dict(name="h_previous", vr=54, causality="local", type="Time",
         description="co-simulation: the previous communication step size when it had input "
                     "derivatives, else 0 (no history)", depends=[]),
    dict(name="first_step_vector", vr=55, shape=(3,), causality="local", type="Dimensionless",
         description="co-simulation: component {i} of the rotation vector Omega of the previous "
                     "step when it had derivatives but no history (Taylor), kept to correct that "
                     "step once its end values are known", depends=[]),
    dict(name="first_step_pending", vr=58, causality="local", type="Dimensionless",
         description="co-simulation: 1 while the previous step awaits that correction, else 0",
         depends=[]),
    # When the angles are computed (model.c, lazy angles): values, so that an FMU state carries
    # them and a replay is bit-identical.
    dict(name="angles_age", vr=59, causality="local", type="Dimensionless",
         description="co-simulation: steps taken since theta was last computed (0: theta is "
                     "that of q)", depends=[]),
    dict(name="angles_change_bound", vr=60, causality="local", type="Angle",
         description="co-simulation: a bound on how far any angle has moved since theta was "
                     "last computed (the sum over those steps of each step's bound, from the "
                     "step's rotation and the singularity distance)", depends=[]),
    dict(name="q0", vr=44, shape=(4,), causality="parameter", type="Dimensionless",
         start=lambda i: 1.0 if i == 1 else 0.0, min=-1.7976931348623157e308, max=1.7976931348623157e308,
         description="initial quaternion, component {i} (scalar first); normalized at "
                     "initialization, zero or non-finite refused"),
]
