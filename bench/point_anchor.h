/* bench/point_anchor.c: PointKinematics' hand-written formula, the benchmark's fixed anchor. */
#ifndef ANGULAR_KINEMATICS_POINT_ANCHOR_H
#define ANGULAR_KINEMATICS_POINT_ANCHOR_H

void ak_anchor_point(const double in[24], double out[18]);

#endif
