/* The per-sequence anchors (bench/anchors_sequences.c, generated once by
 * bench/anchors_sequences.py and frozen): omega_fixed, omega_body, alpha_fixed, alpha_body of one
 * rotation sequence in closed form, y[0..11], with glibc's sin and cos. */
#ifndef ANGULAR_KINEMATICS_ANCHORS_SEQUENCES_H
#define ANGULAR_KINEMATICS_ANCHORS_SEQUENCES_H

typedef void ak_anchor_kernel(const double theta[3], const double theta_dot[3],
                              const double theta_ddot[3], double y[12]);

/* In the order of the sequence Enumeration (AK_SEQUENCES): body123 .. space323. */
extern ak_anchor_kernel *const AK_ANCHORS[24];

#endif
