/* The frozen anchors of attitude_anchor.c once more, under other names, for bench_attitude's
 * --inputs smooth (steps of 0.01 s): the compiler specializes each copy for the one step its
 * loops pass, so the default loops keep the code their counts were recorded with and the smooth
 * loops get the same specialization for their step. Not a new anchor: the same source. */
#define ak_anchor_attitude_step ak_anchor_smooth_attitude_step
#define ak_anchor_quat_to_matrix ak_anchor_smooth_quat_to_matrix
#define ak_anchor_angles_123 ak_anchor_smooth_angles_123
#include "attitude_anchor.c"
