/* The anchors of bench_attitude: the bare quaternion update for a constant omega and
 * the angles of body123 from it, written out once here and frozen. They are copies of the core's
 * ak_attitude_step (with c = {omega, 0, 0, 0}, body frame), ak_quat_to_matrix and
 * ak_attitude_angles (body123) as of 0.3.0, with glibc's sin, cos and atan2: the FMU's core will
 * change (its own elementary functions), and a denominator that moved with it could no longer
 * show whether the FMU got slower. Do not edit them to follow the core. bench_attitude checks
 * them against the core before it times anything (attitude_anchor_check). */
#ifndef ANGULAR_KINEMATICS_BENCH_ATTITUDE_ANCHOR_H
#define ANGULAR_KINEMATICS_BENCH_ATTITUDE_ANCHOR_H

#include <stdbool.h>

/* q := q advanced over h for omega constant in body components; false, q untouched, when the
 * result is not finite. */
bool ak_anchor_attitude_step(const double omega[3], double h, double q[4]);

/* R of a unit q, row-major (v_fixed = R v_body). */
void ak_anchor_quat_to_matrix(const double q[4], double R[3][3]);

/* The body123 angles of R continuing previous (unwrapped, the nearer of the two sets, theta1
 * held at the singular configuration); *distance = cos theta2. True when singular. */
bool ak_anchor_angles_123(double R[3][3], const double previous[3], double theta[3],
                          double *distance);

#endif
