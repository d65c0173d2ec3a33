/* Kinematics of a point P of (or moving over) a rotating body B: its velocity and acceleration in
 * the fixed frame N, and what an accelerometer at P measures.
 *
 * Every vector is given and returned in components of the body frame B. O is a reference point,
 * r the position of P relative to O; r_dot and r_ddot are the first and second derivatives of r
 * taken in B (zero for a point fixed on the body). omega and alpha are the angular velocity and
 * acceleration of B in N; v_O and a_O the velocity and acceleration of O in N; g the gravitational
 * acceleration.
 *
 * Derivation. For any vector u, its derivative in N is its derivative in B plus omega x u (the
 * transport theorem). With p_P = p_O + r:
 *     v_P = v_O + r_dot + omega x r
 * and once more, d/dt (omega x r) in N = alpha x r + omega x r_dot + omega x (r_dot + omega x r)
 * (alpha: the derivative of omega, the same in N and in B since omega x omega = 0), so
 *     a_P = a_O + alpha x r + omega x (omega x r) + 2 omega x r_dot + r_ddot
 * with the parts
 *     a_tangential  = alpha x r
 *     a_centripetal = omega x (omega x r)
 *     a_coriolis    = 2 omega x r_dot
 * and the specific force, the reading of an ideal accelerometer at P:
 *     specific_force = a_P - g.
 *
 * Accuracy: each product is rounded once per term of its cross product, each sum once per term:
 * every output lies within a few units of roundoff of the size of its terms (for a_P:
 * |a_O| + |alpha||r| + |omega|^2 |r| + 2 |omega||r_dot| + |r_ddot|). */
#ifndef AK_POINT_KINEMATICS_H
#define AK_POINT_KINEMATICS_H

#include <stdbool.h>

typedef struct {
    const double *omega, *alpha; /* angular velocity and acceleration of B */
    const double *v_O, *a_O;     /* velocity and acceleration of O */
    const double *r, *r_dot, *r_ddot; /* P relative to O, its derivatives in B */
    const double *g;             /* gravitational acceleration */
} ak_point_inputs;

typedef struct {
    double v_P[3], a_P[3], specific_force[3];
    double a_tangential[3], a_centripetal[3], a_coriolis[3];
} ak_point_outputs;

/* The outputs above from the inputs (each a 3-vector in B components); out may overlap the
 * inputs. Returns whether every output is finite (finite inputs whose products overflow give
 * infinities or NaN). */
bool ak_point_kinematics(const ak_point_inputs *in, ak_point_outputs *out);

/* The change of the outputs along a change d_in of the inputs (forward mode, exact: the outputs
 * are polynomials of the inputs); with d_in a unit vector, a column of the Jacobian. */
void ak_point_kinematics_tangent(const ak_point_inputs *in, const ak_point_inputs *d_in,
                                 ak_point_outputs *d_out);

#endif
