"""EulerRates: the one description of this model (see AngularKinematics/description.py for the
rules: value references are forever, arrays take consecutive ones, `depends` per element)."""

NAME = "EulerRates"
C_PREFIX = "ER"  # of the generated C names: ER_VR_..., ER_VARIABLES
GUID = "{6f0d3c8e-2b1a-4e55-9a53-2f4c1d7e8b90}"
DESCRIPTION = ("Kinematic differential equations of any of the 24 rotation sequences: the first "
               "and second time derivatives of the angles from the angular velocity and its "
               "derivative (body or fixed components)")
SOURCES = ["model.c"]
# The core's sources this model calls (relative to fmu_src/): its FMU compiles and ships these
# alone, with the headers they and the model include (tests/python/test_dead_code.py).
CORE = ["core/sequences.c", "core/kinematics_general.c", "core/kinematics_euler_rates.c",
        "core/kinematics_rates_sequences.c",
        "elementary/elementary_reduce.c"]
# The FMU's documentation/index.html (codegen/documentation.py): these pages or their sections, and
# these figures of documentation/.
DOCUMENTATION = [("docs/models.md", ["Rotation sequences and conventions",
                                     "EulerRates: the inverse map", "FMI behaviour"]),
                 ("docs/cosimulation.md", ["The reference result each FMU carries (FMI-LS-REF)"])]
FIGURES = [("models.svg", "AngularKinematics maps angles and their derivatives to omega and alpha, "
            "EulerRates maps omega and its derivative back to the angle rates",
            "EulerRates, the inverse map of AngularKinematics.")]
CAPABILITIES = dict(provides_directional_derivative=False, can_interpolate_inputs=True,
                    max_output_derivative_order=0)
ENUMERATIONS = {
    "Frame": dict(description="frame of the components of omega and omega_dot",
                  items=[("fixed", "components along the fixed axes n1, n2, n3"),
                         ("body", "components along the body axes b1, b2, b3")]),
}

# The outputs of the cross-check results (scripts/make_cross_check.py; at most 10): alpha_fixed
# and alpha_body are the inputs' alpha.
CROSS_CHECK_OUTPUTS = ([f"{n}[{i}]" for n in ("theta_dot", "theta_ddot") for i in (1, 2, 3)] +
                       ["singularity_distance"])

VARIABLES = [
    dict(name="theta", vr=0, shape=(3,), causality="input", type="Angle",
         description="angle {i} of the rotation sequence (parameter sequence)"),
    dict(name="omega", vr=3, shape=(3,), causality="input", type="AngularVelocity",
         description="component {i} of the angular velocity of the body, in the frame of "
                     "parameter frame"),
    dict(name="omega_dot", vr=6, shape=(3,), causality="input", type="AngularAcceleration",
         description="time derivative of omega[{i}] (the angular acceleration in the frame of "
                     "parameter frame)"),
    # theta_dot[2] never depends on theta[2]: it is a combination of omega with sines and
    # cosines of theta[1] (body-fixed) or theta[3] (space-fixed) only.
    dict(name="theta_dot", vr=9, shape=(3,), causality="output", type="AngularVelocity",
         description="first time derivative of theta[{i}]",
         depends=lambda i: (["theta[1]", "theta[3]"] if i == 2 else
                            ["theta[1]", "theta[2]", "theta[3]"]) +
                           ["omega[1]", "omega[2]", "omega[3]"]),
    dict(name="theta_ddot", vr=12, shape=(3,), causality="output", type="AngularAcceleration",
         description="second time derivative of theta[{i}]",
         depends=["theta", "omega", "omega_dot"]),
    dict(name="alpha_fixed", vr=15, shape=(3,), causality="output", type="AngularAcceleration",
         description="fixed-frame component {i} of the angular acceleration of the body",
         depends=["theta", "omega_dot"]),
    dict(name="alpha_body", vr=18, shape=(3,), causality="output", type="AngularAcceleration",
         description="body-frame component {i} of the angular acceleration of the body",
         depends=["theta", "omega_dot"]),
    dict(name="singularity_distance", vr=21, causality="output", type="Dimensionless",
         description="|det W|: |cos theta[2]| (Tait-Bryan) or |sin theta[2]| (proper Euler); 0 at "
                     "the singular configuration",
         depends=["theta[2]"]),
    dict(name="sequence", vr=22, causality="parameter", type="Sequence", start="body123",
         description="rotation sequence of the angles theta"),
    dict(name="frame", vr=23, causality="parameter", type="Frame", start="fixed",
         description="frame of the components of the inputs omega and omega_dot"),
    dict(name="tolerance", vr=24, causality="parameter", type="Dimensionless", start=1e-4,
         min=0.0, max=1.0, range_note="the range of singularity_distance",
         description="singularity_distance below which a warning is logged (fmi2Warning)"),
]
