/* bench/quaternion_anchor.c: QuaternionKinematics' hand-written formula (body123), the
 * benchmark's fixed anchor. */
#ifndef ANGULAR_KINEMATICS_QUATERNION_ANCHOR_H
#define ANGULAR_KINEMATICS_QUATERNION_ANCHOR_H

void ak_anchor_quaternion(const double in[12], double out[32]);

#endif
