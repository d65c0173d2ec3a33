/*
 * The 24 rotation sequences, as data: three axes and whether they are body-fixed or space-fixed.
 *
 * Axes are numbered 1, 2, 3 (x, y, z of the frame the rotation is about). Angles theta1, theta2,
 * theta3 belong to the first, second and third axis of the name, in that order.
 *
 *   body-fixed ("bodyIJK", intrinsic): theta1 about n_I, then theta2 about the once-rotated axis J,
 *       then theta3 about the twice-rotated axis K:       R = R_I(theta1) R_J(theta2) R_K(theta3)
 *   space-fixed ("spaceIJK", extrinsic): theta1 about n_I, then theta2 about n_J, then theta3 about
 *       n_K, every axis fixed in N:                       R = R_K(theta3) R_J(theta2) R_I(theta1)
 *
 * R_i(x) is the right-handed rotation by x about axis i, and R maps body components to fixed
 * components: v_fixed = R v_body. These are the semantics of sympy.physics.vector's
 * orient_body_fixed(N, angles, 'IJK') and orient_space_fixed(N, angles, 'IJK').
 *
 * The table (sequences.c) is generated from codegen/project.py.
 * Table order (index 0..23) is the order of the items of the `sequence` Enumeration: the six
 * Tait-Bryan sequences, then the six proper Euler sequences, body-fixed first, then the same twelve
 * space-fixed. Index 0, body123, is the default.
 */
#ifndef ANGULAR_KINEMATICS_SEQUENCES_H
#define ANGULAR_KINEMATICS_SEQUENCES_H

typedef enum { AK_BODY_FIXED = 0, AK_SPACE_FIXED = 1 } ak_sequence_kind;

typedef struct {
    const char *name;          /* "body123" ... "space323" */
    int axes[3];               /* 1, 2 or 3, in the order of theta1, theta2, theta3 */
    ak_sequence_kind kind;
    int proper_euler;          /* 1 when the first and the last axis are the same (e.g. 3-1-3) */
    const char *description;   /* one line, for documentation and Enumeration items */
} ak_sequence;

#define AK_SEQUENCE_COUNT 24
#define AK_SEQUENCE_DEFAULT 0 /* body123 */

extern const ak_sequence AK_SEQUENCES[AK_SEQUENCE_COUNT];

#endif
