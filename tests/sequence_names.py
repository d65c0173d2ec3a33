"""The 24 rotation sequences in the order of the `sequence` Enumeration (item value = index + 1),
with the descriptions of fmu_src/sequences.c (tests/test_model_description.py checks they agree)."""

DESCRIPTIONS = {
    "body123": "body-fixed 1-2-3 (Tait-Bryan, Cardan x-y'-z'')",
    "body132": "body-fixed 1-3-2 (Tait-Bryan)",
    "body213": "body-fixed 2-1-3 (Tait-Bryan)",
    "body231": "body-fixed 2-3-1 (Tait-Bryan)",
    "body312": "body-fixed 3-1-2 (Tait-Bryan)",
    "body321": "body-fixed 3-2-1 (Tait-Bryan, yaw-pitch-roll)",
    "body121": "body-fixed 1-2-1 (proper Euler)",
    "body131": "body-fixed 1-3-1 (proper Euler)",
    "body212": "body-fixed 2-1-2 (proper Euler)",
    "body232": "body-fixed 2-3-2 (proper Euler)",
    "body313": "body-fixed 3-1-3 (proper Euler, z-x'-z'')",
    "body323": "body-fixed 3-2-3 (proper Euler, z-y'-z'')",
    "space123": "space-fixed 1-2-3 (Tait-Bryan, x-y-z)",
    "space132": "space-fixed 1-3-2 (Tait-Bryan)",
    "space213": "space-fixed 2-1-3 (Tait-Bryan)",
    "space231": "space-fixed 2-3-1 (Tait-Bryan)",
    "space312": "space-fixed 3-1-2 (Tait-Bryan)",
    "space321": "space-fixed 3-2-1 (Tait-Bryan)",
    "space121": "space-fixed 1-2-1 (proper Euler)",
    "space131": "space-fixed 1-3-1 (proper Euler)",
    "space212": "space-fixed 2-1-2 (proper Euler)",
    "space232": "space-fixed 2-3-2 (proper Euler)",
    "space313": "space-fixed 3-1-3 (proper Euler)",
    "space323": "space-fixed 3-2-3 (proper Euler)",
}
SEQUENCES = list(DESCRIPTIONS)
TAIT_BRYAN = ("123", "132", "213", "231", "312", "321")
PROPER_EULER = ("121", "131", "212", "232", "313", "323")
assert SEQUENCES == [kind + order for kind in ("body", "space") for order in TAIT_BRYAN + PROPER_EULER]


def sequence_description(name):
    return DESCRIPTIONS[name]
