/* The 24 rotation sequences: see sequences.h for the conventions and the order. */
#include "sequences.h"

#include <string.h>

const ak_sequence AK_SEQUENCES[AK_SEQUENCE_COUNT] = {
    {"body123", {1, 2, 3}, AK_BODY_FIXED, 0, "body-fixed 1-2-3 (Tait-Bryan, Cardan x-y'-z'')"},
    {"body132", {1, 3, 2}, AK_BODY_FIXED, 0, "body-fixed 1-3-2 (Tait-Bryan)"},
    {"body213", {2, 1, 3}, AK_BODY_FIXED, 0, "body-fixed 2-1-3 (Tait-Bryan)"},
    {"body231", {2, 3, 1}, AK_BODY_FIXED, 0, "body-fixed 2-3-1 (Tait-Bryan)"},
    {"body312", {3, 1, 2}, AK_BODY_FIXED, 0, "body-fixed 3-1-2 (Tait-Bryan)"},
    {"body321", {3, 2, 1}, AK_BODY_FIXED, 0, "body-fixed 3-2-1 (Tait-Bryan, yaw-pitch-roll)"},
    {"body121", {1, 2, 1}, AK_BODY_FIXED, 1, "body-fixed 1-2-1 (proper Euler)"},
    {"body131", {1, 3, 1}, AK_BODY_FIXED, 1, "body-fixed 1-3-1 (proper Euler)"},
    {"body212", {2, 1, 2}, AK_BODY_FIXED, 1, "body-fixed 2-1-2 (proper Euler)"},
    {"body232", {2, 3, 2}, AK_BODY_FIXED, 1, "body-fixed 2-3-2 (proper Euler)"},
    {"body313", {3, 1, 3}, AK_BODY_FIXED, 1, "body-fixed 3-1-3 (proper Euler, z-x'-z'')"},
    {"body323", {3, 2, 3}, AK_BODY_FIXED, 1, "body-fixed 3-2-3 (proper Euler, z-y'-z'')"},
    {"space123", {1, 2, 3}, AK_SPACE_FIXED, 0, "space-fixed 1-2-3 (Tait-Bryan, x-y-z)"},
    {"space132", {1, 3, 2}, AK_SPACE_FIXED, 0, "space-fixed 1-3-2 (Tait-Bryan)"},
    {"space213", {2, 1, 3}, AK_SPACE_FIXED, 0, "space-fixed 2-1-3 (Tait-Bryan)"},
    {"space231", {2, 3, 1}, AK_SPACE_FIXED, 0, "space-fixed 2-3-1 (Tait-Bryan)"},
    {"space312", {3, 1, 2}, AK_SPACE_FIXED, 0, "space-fixed 3-1-2 (Tait-Bryan)"},
    {"space321", {3, 2, 1}, AK_SPACE_FIXED, 0, "space-fixed 3-2-1 (Tait-Bryan)"},
    {"space121", {1, 2, 1}, AK_SPACE_FIXED, 1, "space-fixed 1-2-1 (proper Euler)"},
    {"space131", {1, 3, 1}, AK_SPACE_FIXED, 1, "space-fixed 1-3-1 (proper Euler)"},
    {"space212", {2, 1, 2}, AK_SPACE_FIXED, 1, "space-fixed 2-1-2 (proper Euler)"},
    {"space232", {2, 3, 2}, AK_SPACE_FIXED, 1, "space-fixed 2-3-2 (proper Euler)"},
    {"space313", {3, 1, 3}, AK_SPACE_FIXED, 1, "space-fixed 3-1-3 (proper Euler)"},
    {"space323", {3, 2, 3}, AK_SPACE_FIXED, 1, "space-fixed 3-2-3 (proper Euler)"},
};

int ak_sequence_index(const char *name) {
    if (name == NULL) {
        return -1;
    }
    for (int k = 0; k < AK_SEQUENCE_COUNT; k++) {
        if (strcmp(AK_SEQUENCES[k].name, name) == 0) {
            return k;
        }
    }
    return -1;
}
