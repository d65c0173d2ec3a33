/* Rotation matrices for the core's unit tests; see rotation_matrices.h. */
#include "rotation_matrices.h"

#include <math.h>

void elementary_rotation(int axis, double angle, double M[3][3], double dM[3][3]) {
    const double s = sin(angle), c = cos(angle);
    /* The rotation acts in the plane of the two other axes, i then j in cyclic order. */
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) {
            M[r][k] = (r == k) ? 1.0 : 0.0;
            dM[r][k] = 0.0;
        }
    }
    M[i][i] = c;
    M[i][j] = -s;
    M[j][i] = s;
    M[j][j] = c;
    dM[i][i] = -s;
    dM[i][j] = -c;
    dM[j][i] = c;
    dM[j][j] = -s;
}

void multiply(double A[3][3], double B[3][3], double C[3][3]) {
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) {
            C[r][k] = A[r][0] * B[0][k] + A[r][1] * B[1][k] + A[r][2] * B[2][k];
        }
    }
}
