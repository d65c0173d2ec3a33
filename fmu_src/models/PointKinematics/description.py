"""PointKinematics: the one description of this model (see AngularKinematics/description.py for the
rules: value references are forever, arrays take consecutive ones, `depends` per element)."""

NAME = "PointKinematics"
C_PREFIX = "PK"  # of the generated C names: PK_VR_..., PK_VARIABLES
GUID = "{4289c8dc-268d-4454-a847-afb72164dd53}"
DESCRIPTION = ("Velocity and acceleration of a point of a rotating body, and the specific force an "
               "accelerometer there measures, from the body's angular velocity and acceleration, "
               "the motion of a reference point and the point's position relative to it (body "
               "components)")
SOURCES = ["model.c"]
# The core's sources this model calls (relative to fmu_src/): its FMU compiles and ships these
# alone, with the headers they and the model include (tests/python/test_dead_code.py).
CORE = ["core/point_kinematics.c"]
# The core's unit test (tests/c/, registered with ctest by CMake from this list).
CORE_TESTS = ["tests/c/test_point_kinematics.c"]
# The FMU's documentation/index.html (codegen/documentation.py): these pages or their sections.
DOCUMENTATION = [("docs/point_kinematics.md", None)]
FIGURES = []
CAPABILITIES = dict(provides_directional_derivative=True, can_interpolate_inputs=True,
                    max_output_derivative_order=0)
ENUMERATIONS = {}

# Component i of a x b is a[j] b[k] - a[k] b[j], (i, j, k) a cyclic order of (1, 2, 3): it never
# depends on a[i] or b[i].
_CYCLIC = {1: (2, 3), 2: (3, 1), 3: (1, 2)}


def _cross(a, b, i):
    j, k = _CYCLIC[i]
    return [f"{a}[{j}]", f"{a}[{k}]", f"{b}[{j}]", f"{b}[{k}]"]


def _centripetal(i):
    """omega x (omega x r), component i: omega[i] (omega . r) - r[i] |omega|^2, every omega and
    every r (only omega[i]^2 r[i] cancels)."""
    return ["omega[1]", "omega[2]", "omega[3]", "r[1]", "r[2]", "r[3]"]


def _v_P(i):
    return [f"v_O[{i}]", f"r_dot[{i}]"] + _cross("omega", "r", i)


def _a_P(i):
    return ([f"a_O[{i}]", f"r_ddot[{i}]"] + _cross("alpha", "r", i) + _centripetal(i) +
            _cross("omega", "r_dot", i))


def _vector(name, vr, causality, type, description, **more):
    return dict(name=name, vr=vr, shape=(3,), causality=causality, type=type,
                description=description, **more)


# The outputs of the cross-check results (scripts/make_cross_check.py; at most 10): the parts of
# a_P follow from these and the inputs.
CROSS_CHECK_OUTPUTS = [f"{n}[{i}]" for n in ("v_P", "a_P", "specific_force") for i in (1, 2, 3)]

VARIABLES = [
    _vector("omega", 0, "input", "AngularVelocity",
            "component {i} of the angular velocity of the body (body components)"),
    _vector("alpha", 3, "input", "AngularAcceleration",
            "component {i} of the angular acceleration of the body (body components)"),
    _vector("v_O", 6, "input", "Velocity",
            "component {i} of the velocity of the reference point O in the fixed frame (body "
            "components)"),
    _vector("a_O", 9, "input", "Acceleration",
            "component {i} of the acceleration of the reference point O in the fixed frame (body "
            "components)"),
    _vector("r", 12, "input", "Length",
            "component {i} of the position of the point P relative to O (body components)"),
    _vector("r_dot", 15, "input", "Velocity",
            "component {i} of the velocity of P relative to the body: the derivative of r in the "
            "body frame (0 for a point fixed on the body)"),
    _vector("r_ddot", 18, "input", "Acceleration",
            "component {i} of the acceleration of P relative to the body: the second derivative "
            "of r in the body frame (0 for a point fixed on the body)"),
    _vector("g", 21, "input", "Acceleration",
            "component {i} of the gravitational acceleration (body components; 0: no gravity)"),
    _vector("v_P", 24, "output", "Velocity",
            "component {i} of the velocity of P in the fixed frame: v_O + omega x r + r_dot "
            "(body components)", depends=_v_P),
    _vector("a_P", 27, "output", "Acceleration",
            "component {i} of the acceleration of P in the fixed frame: a_O + alpha x r + "
            "omega x (omega x r) + 2 omega x r_dot + r_ddot (body components)", depends=_a_P),
    _vector("specific_force", 30, "output", "Acceleration",
            "component {i} of the specific force at P, what an accelerometer there measures: "
            "a_P - g (body components)", depends=lambda i: _a_P(i) + [f"g[{i}]"]),
    _vector("a_tangential", 33, "output", "Acceleration",
            "component {i} of the tangential acceleration of P: alpha x r (body components)",
            depends=lambda i: _cross("alpha", "r", i)),
    _vector("a_centripetal", 36, "output", "Acceleration",
            "component {i} of the centripetal acceleration of P: omega x (omega x r) (body "
            "components)", depends=_centripetal),
    _vector("a_coriolis", 39, "output", "Acceleration",
            "component {i} of the Coriolis acceleration of P: 2 omega x r_dot (body components)",
            depends=lambda i: _cross("omega", "r_dot", i)),
]
