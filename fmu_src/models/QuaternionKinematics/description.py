"""QuaternionKinematics: the one description of this model (see AngularKinematics/description.py
for the rules: value references are forever, arrays take consecutive ones, `depends` per
element)."""

NAME = "QuaternionKinematics"
C_PREFIX = "QK"  # of the generated C names: QK_VR_..., QK_VARIABLES
GUID = "{a48f0945-5728-425c-a993-40484d7d9f7e}"
DESCRIPTION = ("Angular velocity and acceleration of a body from its attitude quaternion and the "
               "quaternion's first and second time derivatives (|q| need not be 1), with the "
               "rotation matrix and the angles of any of the 24 rotation sequences and their "
               "derivatives")
SOURCES = ["model.c"]
# The core's sources this model calls (relative to fmu_src/): its FMU compiles and ships these
# alone, with the headers they and the model include (tests/python/test_dead_code.py).
CORE = ["core/sequences.c", "core/kinematics_general.c", "core/kinematics_rotation_matrix.c",
        "core/kinematics_partials.c",
        "core/kinematics_euler_rates.c", "core/kinematics_rates_sequences.c",
        "core/kinematics_general_jacobian.c",
        "core/attitude_angles.c", "core/attitude_angle_sines.c",
        "core/quaternion_kinematics.c",
        "elementary/elementary_reduce.c", "elementary/elementary_atan2.c"]
# The core's unit test (tests/c/, registered with ctest by CMake from this list).
CORE_TESTS = ["tests/c/test_quaternion_kinematics.c"]
# The FMU's documentation/index.html (codegen/documentation.py): these pages or their sections.
DOCUMENTATION = [("docs/quaternion_kinematics.md", None)]
FIGURES = []
CAPABILITIES = dict(provides_directional_derivative=True, can_interpolate_inputs=True,
                    max_output_derivative_order=0)
ENUMERATIONS = {}

# The outputs of the cross-check results (scripts/make_cross_check.py; at most 10): the fixed-frame
# ones are R times these, and R follows from theta.
CROSS_CHECK_OUTPUTS = ([f"{n}[{i}]" for n in ("omega_body", "alpha_body", "theta")
                        for i in (1, 2, 3)] + ["q_norm"])


def _vector(name, vr, causality, type, description, shape=(3,), **more):
    return dict(name=name, vr=vr, shape=shape, causality=causality, type=type,
                description=description, **more)


VARIABLES = [
    _vector("q", 0, "input", "Dimensionless",
            "component {i} of the attitude quaternion (scalar first, Hamilton product, "
            "v_fixed = q v_body q*); its length need not be 1, and q and -q are the same "
            "attitude", shape=(4,), start=lambda i: 1.0 if i == 1 else 0.0),
    _vector("q_dot", 4, "input", "Frequency", "first time derivative of q[{i}]", shape=(4,)),
    _vector("q_ddot", 8, "input", "FrequencyRate", "second time derivative of q[{i}]",
            shape=(4,)),
    _vector("omega_fixed", 12, "output", "AngularVelocity",
            "fixed-frame component {i} of the angular velocity of the body: 2 vec(u' u*), "
            "u = q / |q|", depends=["q", "q_dot"]),
    _vector("omega_body", 15, "output", "AngularVelocity",
            "body-frame component {i} of the angular velocity of the body: 2 vec(u* u'), "
            "u = q / |q|", depends=["q", "q_dot"]),
    _vector("alpha_fixed", 18, "output", "AngularAcceleration",
            "fixed-frame component {i} of the angular acceleration of the body: 2 vec(u'' u*)",
            depends=["q", "q_dot", "q_ddot"]),
    _vector("alpha_body", 21, "output", "AngularAcceleration",
            "body-frame component {i} of the angular acceleration of the body: 2 vec(u* u'')",
            depends=["q", "q_dot", "q_ddot"]),
    _vector("R", 24, "output", "Dimensionless",
            "direction cosine matrix of q / |q|, row {i} column {j}: v_fixed = R v_body",
            shape=(3, 3), depends=["q"]),
    dict(name="q_norm", vr=33, causality="output", type="Dimensionless",
         description="|q|, the length of the input quaternion", depends=["q"]),
    _vector("theta", 34, "output", "Angle",
            "angle {i} of the rotation sequence (parameter sequence) of the attitude q / |q|: "
            "the principal values", depends=["q"]),
    _vector("theta_dot", 37, "output", "AngularVelocity", "first time derivative of theta[{i}]",
            depends=["q", "q_dot"]),
    _vector("theta_ddot", 40, "output", "AngularAcceleration",
            "second time derivative of theta[{i}]", depends=["q", "q_dot", "q_ddot"]),
    dict(name="singularity_distance", vr=43, causality="output", type="Dimensionless",
         description="|det W|: |cos theta[2]| (Tait-Bryan) or |sin theta[2]| (proper Euler); 0 at "
                     "the singular configuration, where theta_dot and theta_ddot are not defined",
         depends=["q"]),
    dict(name="sequence", vr=44, causality="parameter", type="Sequence", start="body123",
         description="rotation sequence of the angles theta"),
    dict(name="tolerance", vr=45, causality="parameter", type="Dimensionless", start=1e-4,
         min=0.0, max=1.0, range_note="the range of singularity_distance",
         description="singularity_distance below which a warning is logged (fmi2Warning)"),
]
