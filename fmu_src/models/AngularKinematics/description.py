"""AngularKinematics: the one description of this model. `python -m codegen` writes from it the
variable table (AngularKinematics_variables.{h,c}), its modelDescription.xml (of which the
repository root holds a copy), the source list of CMake and <SourceFiles>, the variable tables of
the docs and the FMU's documentation page.

Value references are written here and never change or get reused: a new variable takes a new
value reference above every one in use (tests/python/test_value_references.py pins those of 0.2).
An array of shape (3,) or (3, 3) takes consecutive value references from `vr`, row-major.
`depends`: the inputs an output structurally depends on, as whole inputs ("theta") or, where it
differs per element, a function of the element's indices (1-based) giving element names."""

NAME = "AngularKinematics"
C_PREFIX = "KIN"  # of the generated C names: KIN_VR_..., KIN_VARIABLES; set here only (codegen reads it)
GUID = "{c3391885-ba93-4824-bb36-df39703b63ee}"
DESCRIPTION = ("Angular velocity and angular acceleration of a rigid body from the angles of any "
               "of the 24 rotation sequences and their first and second time derivatives; "
               "rotation matrix, quaternion and partial angular velocity matrices")
SOURCES = ["model.c"]  # this folder's hand-written glue; the generated table is added
# The core's sources this model calls (relative to fmu_src/): its FMU compiles and ships these
# alone, with the headers they and the model include (tests/python/test_dead_code.py).
CORE = ["core/sequences.c", "core/kinematics_general.c", "core/kinematics_rotation.c",
        "core/kinematics_rotation_matrix.c", "core/kinematics_partials.c", "core/kinematics_sequences.c",
        "core/kinematics_general_jacobian.c", "elementary/elementary_reduce.c",
        "elementary/elementary_atan.c"]
# The FMU's documentation/index.html (codegen/documentation.py): these pages or their sections, and
# these figures of documentation/.
DOCUMENTATION = [("docs/models.md", ["What it computes", "Rotation sequences and conventions",
                                     "FMI behaviour", "Capabilities"]),
                 ("docs/cosimulation.md", ["The reference result each FMU carries (FMI-LS-REF)"])]
FIGURES = [("tumbling_body.png", "omega and alpha of a tumbling body, fixed and body components",
            "A tumbling body simulated with fmpy: the angular velocity and the angular acceleration "
            "in the fixed frame and in the body frame; grey bands: theta[2] within 0.1 rad of "
            "gimbal lock."),
           ("models.svg", "AngularKinematics maps angles and their derivatives to omega and alpha, "
            "EulerRates maps omega and its derivative back to the angle rates",
            "AngularKinematics, the forward map, and EulerRates, the inverse map.")]
CAPABILITIES = dict(provides_directional_derivative=True, can_interpolate_inputs=True,
                    max_output_derivative_order=1)


def _others(j):
    """theta elements other than theta[j]: column j of W does not depend on theta[j]."""
    return [f"theta[{k}]" for k in (1, 2, 3) if k != j]


def _others_and_rates(i, j):
    return _others(j) + [f"theta_dot[{k}]" for k in (1, 2, 3) if k != j]


# The outputs of the cross-check results (scripts/make_cross_check.py; the rules recommend at most
# 10): omega and alpha in the fixed frame are R(q) times the body ones.
CROSS_CHECK_OUTPUTS = ([f"{n}[{i}]" for n in ("omega_body", "alpha_body") for i in (1, 2, 3)] +
                       [f"q[{i}]" for i in (1, 2, 3, 4)])

VARIABLES = [
    dict(name="theta", vr=0, shape=(3,), causality="input", type="Angle",
         description="angle {i} of the rotation sequence (parameter sequence)"),
    dict(name="theta_dot", vr=3, shape=(3,), causality="input", type="AngularVelocity",
         description="first time derivative of theta[{i}]"),
    dict(name="theta_ddot", vr=6, shape=(3,), causality="input", type="AngularAcceleration",
         description="second time derivative of theta[{i}]"),
    dict(name="omega_fixed", vr=9, shape=(3,), causality="output", type="AngularVelocity",
         description="fixed-frame component {i} of the angular velocity of the body",
         depends=["theta", "theta_dot"]),
    dict(name="omega_body", vr=12, shape=(3,), causality="output", type="AngularVelocity",
         description="body-frame component {i} of the angular velocity of the body",
         depends=["theta", "theta_dot"]),
    dict(name="alpha_fixed", vr=15, shape=(3,), causality="output", type="AngularAcceleration",
         description="fixed-frame component {i} of the angular acceleration of the body",
         depends=["theta", "theta_dot", "theta_ddot"]),
    dict(name="alpha_body", vr=18, shape=(3,), causality="output", type="AngularAcceleration",
         description="body-frame component {i} of the angular acceleration of the body",
         depends=["theta", "theta_dot", "theta_ddot"]),
    dict(name="R", vr=21, shape=(3, 3), causality="output", type="Dimensionless", group="lazy",
         description="direction cosine matrix, row {i} column {j}: v_fixed = R v_body",
         depends=["theta"]),
    dict(name="q", vr=30, shape=(4,), causality="output", type="Dimensionless", group="lazy",
         description="unit quaternion of the orientation, component {i} (scalar first: q[1] is "
                     "the scalar part, q[1] >= 0)",
         depends=["theta"]),
    dict(name="W_fixed", vr=34, shape=(3, 3), causality="output", type="Dimensionless",
         group="lazy",
         description="partial angular velocity matrix, fixed components: omega_fixed = W_fixed "
                     "theta_dot, row {i} column {j}",
         depends=lambda i, j: _others(j)),
    dict(name="W_body", vr=43, shape=(3, 3), causality="output", type="Dimensionless",
         group="lazy",
         description="partial angular velocity matrix, body components: omega_body = W_body "
                     "theta_dot, row {i} column {j}",
         depends=lambda i, j: _others(j)),
    dict(name="W_fixed_dot", vr=52, shape=(3, 3), causality="output", type="Frequency",
         group="lazy", description="time derivative of W_fixed[{i},{j}]",
         depends=_others_and_rates),
    dict(name="W_body_dot", vr=61, shape=(3, 3), causality="output", type="Frequency",
         group="lazy", description="time derivative of W_body[{i},{j}]",
         depends=_others_and_rates),
    dict(name="rotation_angle", vr=71, causality="output", type="Angle",
         description="angle of the rotation that takes the fixed frame to the body frame about "
                     "one axis (Euler's theorem), in [0, pi]: 2 atan2(|(q[2], q[3], q[4])|, q[1])",
         computed_by=("ak_rotation_angle", "q")),
    dict(name="sequence", vr=70, causality="parameter", type="Sequence", start="body123",
         description="rotation sequence of the angles theta"),
]
