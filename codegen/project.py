"""Facts of the whole project, written once: the version, the log categories, the rotation
sequences, the declared types and the source files of the core and the FMI layer. Each model adds
its own description (fmu_src/models/<Model>/description.py); `python -m codegen` writes every file
that repeats these facts (docs/architecture.md lists them)."""
import pathlib

VERSION = "0.4.0"
AUTHOR = "AngularKinematics developers"

# name, description: the order is the order of the C enum ak_log_category and of <LogCategories>.
LOG_CATEGORIES = [
    ("logStatusError",
     "Every call that returns fmi2Error, with the function, the variable and the value"),
    ("logStatusWarning", "Calls that return fmi2Warning or fmi2Discard"),
    ("logCalls", "Trace of every FMI call with its arguments, and of every evaluation of the model"),
]

# The 24 rotation sequences in the order of the `sequence` Enumeration (item value = index + 1):
# the six Tait-Bryan orders, then the six proper Euler orders, body-fixed first, then the same
# twelve space-fixed. The name gives kind and axes; the note is the rest of the description.
TAIT_BRYAN = ("123", "132", "213", "231", "312", "321")
PROPER_EULER = ("121", "131", "212", "232", "313", "323")
_NOTES = {
    "body123": "Tait-Bryan, Cardan x-y'-z''", "body321": "Tait-Bryan, yaw-pitch-roll",
    "body313": "proper Euler, z-x'-z''", "body323": "proper Euler, z-y'-z''",
    "space123": "Tait-Bryan, x-y-z",
}
SEQUENCES = [kind + order for kind in ("body", "space") for order in TAIT_BRYAN + PROPER_EULER]
DEFAULT_SEQUENCE = "body123"


def sequence_axes(name):
    """(1, 2, 3) for body123: the axes of theta[1], theta[2], theta[3]."""
    return tuple(int(c) for c in name[-3:])


def sequence_is_proper_euler(name):
    return name[-3:] in PROPER_EULER


def sequence_table_index(name):
    """The C designator of the sequence in the core's tables by its facts (kind, proper Euler,
    first and second axis, 0-based): "[AK_BODY_FIXED][0][0][1]" for body123."""
    axes = sequence_axes(name)
    kind = "AK_SPACE_FIXED" if name.startswith("space") else "AK_BODY_FIXED"
    return f"[{kind}][{int(sequence_is_proper_euler(name))}][{axes[0] - 1}][{axes[1] - 1}]"


def sequence_description(name):
    kind = "body-fixed" if name.startswith("body") else "space-fixed"
    order = "-".join(name[-3:])
    family = "proper Euler" if sequence_is_proper_euler(name) else "Tait-Bryan"
    return f"{kind} {order} ({_NOTES.get(name, family)})"


# Declared types (<SimpleType> of every modelDescription.xml): quantity, unit, display unit.
TYPES = {
    "Angle": ("Angle", "rad", "deg"),
    "AngularVelocity": ("AngularVelocity", "rad/s", "deg/s"),
    "AngularAcceleration": ("AngularAcceleration", "rad/s2", "deg/s2"),
    "Dimensionless": (None, "", None),
    "Frequency": ("Frequency", "1/s", None),
}
# Declared types written only into the modelDescription.xml of a model that uses them.
OPTIONAL_TYPES = {
    "Time": ("Time", "s", None),
    "Length": ("Length", "m", None),
    "Velocity": ("Velocity", "m/s", None),
    "Acceleration": ("Acceleration", "m/s2", None),
    "FrequencyRate": ("FrequencyRate", "1/s2", None),
}
# The units of the optional types: the SI base units they are made of (<BaseUnit> attributes).
OPTIONAL_UNITS = {"s": 's="1"', "m": 'm="1"', "m/s": 'm="1" s="-1"', "m/s2": 'm="1" s="-2"',
                  "1/s2": 's="-2"'}
# Enumerations every model may use; a model's description can add its own.
ENUMERATIONS = {
    "Sequence": dict(
        description="rotation sequence: body-fixed (intrinsic) or space-fixed (extrinsic), axes "
                    "in the order of theta[1], theta[2], theta[3]",
        items=[(name, sequence_description(name)) for name in SEQUENCES]),
}

# Sources, relative to fmu_src/, in the order they are compiled and listed in <SourceFiles>: these
# first, in the order they have always had, then any other file of fmu_src/core/ and
# fmu_src/elementary/ by name (a model's new core file needs no line here).
# The core calls the project's own elementary functions (fmu_src/elementary/, not libm's sin, cos,
# atan, atan2): they are part of it.
_CORE_SOURCES_FIRST = ["core/sequences.c", "core/kinematics_general.c", "core/kinematics_rotation.c",
                       "core/kinematics_rotation_matrix.c", "core/kinematics_partials.c",
                       "core/kinematics_euler_rates.c", "core/kinematics_rates_sequences.c",
                       "core/kinematics_sequences.c",
                       "core/kinematics_general_jacobian.c",
                       "core/attitude.c", "core/attitude_angles.c",
                       "elementary/elementary_reduce.c", "elementary/elementary_atan.c",
                       "elementary/elementary_atan2.c"]
_CORE_HEADERS_FIRST = ["core/sequences.h", "core/kinematics_general.h", "core/kinematics_chain.h",
                       "core/kinematics_sequences.h", "core/kinematics_general_jacobian.h",
                       "core/attitude.h", "core/attitude_angles.h", "core/attitude_sequences.h",
                       "elementary/elementary.h", "elementary/elementary_sincos_three.h",
                       "elementary/elementary_arc_kernel.h", "elementary/elementary_double_double.h",
                       "elementary/elementary_coefficients.h"]


def _core_files(first, suffix):
    fmu_src = pathlib.Path(__file__).resolve().parent.parent / "fmu_src"
    found = sorted(str(path.relative_to(fmu_src)) for folder in ("core", "elementary")
                   for path in (fmu_src / folder).glob(f"*{suffix}"))
    return [f for f in first if f in found] + [f for f in found if f not in first]


CORE_SOURCES = _core_files(_CORE_SOURCES_FIRST, ".c")
CORE_HEADERS = _core_files(_CORE_HEADERS_FIRST, ".h")
# The FMI runtime under both FMI layers (fmu_src/runtime/), FMI-independent.
RUNTIME_SOURCES = ["runtime/instance.c", "runtime/lifecycle.c", "runtime/values.c",
                   "runtime/stepping.c", "runtime/continuous.c", "runtime/derivatives.c",
                   "runtime/fmu_states.c"]
RUNTIME_HEADERS = ["runtime/runtime.h", "runtime/instance.h", "common/ak_bytes.h",
                   "common/ak_compiler.h", "models/model.h", "models/log_categories.h"]
# beside every model: the runtime, the model-side logging and the chain rule of derived outputs
MODEL_SOURCES = RUNTIME_SOURCES + ["models/model_log.c", "models/model_derived.c"]
FMI2_SOURCES = ["fmi2/fmi2_state_machine.c", "fmi2/fmi2_lifecycle.c", "fmi2/fmi2_values.c",
                "fmi2/fmi2_stepping.c"]
FMI2_HEADERS = ["fmi2/fmi2_layer.h"] + RUNTIME_HEADERS

# The models, each a folder fmu_src/models/<name>/ with description.py, each built as an FMI 2.0
# FMU (dist/<name>.fmu) and an FMI 3.0 FMU (dist/fmi3/<name>.fmu). The one list: CMake reads it
# from cmake/generated.cmake, the scripts and the tests from here (import codegen.project).
MODELS = ["AngularKinematics", "EulerRates", "AttitudePropagator", "PointKinematics", "QuaternionKinematics"]
FMI3_MODELS = MODELS  # the same list under its former name, while tests still read it

# The model whose modelDescription.xml the repository root holds a generated copy of (the layout
# the project promises); its own lives in its folder like every model's.
ROOT_MODEL_DESCRIPTION = "AngularKinematics"
