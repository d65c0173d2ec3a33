/* Rotation matrices built from first principles for the core's unit tests: the expected values
 * come from products of elementary rotations, not from the core's own formulas. */
#ifndef ANGULAR_KINEMATICS_TEST_ROTATION_MATRICES_H
#define ANGULAR_KINEMATICS_TEST_ROTATION_MATRICES_H

/* M = the right-handed rotation by angle about axis (0, 1, 2 for axes 1, 2, 3), dM = dM/dangle. */
void elementary_rotation(int axis, double angle, double M[3][3], double dM[3][3]);

/* C = A B. */
void multiply(double A[3][3], double B[3][3], double C[3][3]);

#endif
