/* The anchors for every sequence: omega_fixed, omega_body, alpha_fixed, alpha_body
 * (y[0..11]) in closed form, generated ONCE by bench/anchors_sequences.py (sympy, from
 * elementary rotation matrices; nothing of the FMU's code) and frozen on purpose: an
 * anchor must not move with the code it judges. Do not edit; do not regenerate but to
 * make new anchors (docs/performance.md). */
#include "anchors_sequences.h"

#include <math.h>


void ak_anchor_body123(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s2*td3;
    const double x1 = c1*td2;
    const double x2 = c2*td3;
    const double x3 = s1*x2;
    const double x4 = s1*td2;
    const double x5 = c1*x2;
    const double x6 = s3*td2;
    const double x7 = c2*td1;
    const double x8 = s2*td1;
    const double x9 = c2*tdd3;
    const double x10 = c2*tdd1;
    const double x11 = c3*td2;
    const double x12 = td1*x2;
    y[0] = td1 + x0;
    y[1] = x1 - x3;
    y[2] = x4 + x5;
    y[3] = c3*x7 + x6;
    y[4] = c3*td2 - s3*x7;
    y[5] = td3 + x8;
    y[6] = s2*tdd3 + td2*x2 + tdd1;
    y[7] = c1*tdd2 + s1*s2*td2*td3 - s1*x9 - td1*x4 - td1*x5;
    y[8] = c1*x9 + s1*tdd2 + td1*x1 - td1*x3 - x0*x1;
    y[9] = c3*x10 + s3*tdd2 - s3*x12 + td3*x11 - x11*x8;
    y[10] = c3*tdd2 - c3*x12 + s2*s3*td1*td2 - s3*x10 - td3*x6;
    y[11] = s2*tdd1 + td2*x7 + tdd3;
}

void ak_anchor_body132(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s2*td3;
    const double x1 = s1*td2;
    const double x2 = c2*td3;
    const double x3 = c1*x2;
    const double x4 = c1*td2;
    const double x5 = s1*x2;
    const double x6 = s3*td2;
    const double x7 = c2*td1;
    const double x8 = s2*td1;
    const double x9 = c3*td2;
    const double x10 = td1*x2;
    y[0] = td1 - x0;
    y[1] = -x1 + x3;
    y[2] = x4 + x5;
    y[3] = c3*x7 - x6;
    y[4] = td3 - x8;
    y[5] = s3*x7 + x9;
    y[6] = -s2*tdd3 - td2*x2 + tdd1;
    y[7] = c1*c2*tdd3 - s1*tdd2 - td1*x4 - td1*x5 - x0*x4;
    y[8] = c1*tdd2 + c2*s1*tdd3 - td1*x1 + td1*x3 - x0*x1;
    y[9] = c2*c3*tdd1 - s3*tdd2 - s3*x10 - td3*x9 - x8*x9;
    y[10] = -s2*tdd1 - td2*x7 + tdd3;
    y[11] = c2*s3*tdd1 + c3*tdd2 + c3*x10 - td3*x6 - x6*x8;
}

void ak_anchor_body213(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c1*td2;
    const double x1 = c2*td3;
    const double x2 = s1*x1;
    const double x3 = s2*td3;
    const double x4 = s1*td2;
    const double x5 = c1*x1;
    const double x6 = c3*td2;
    const double x7 = c2*td1;
    const double x8 = s3*td2;
    const double x9 = s2*td1;
    const double x10 = td1*x1;
    y[0] = x0 + x2;
    y[1] = td1 - x3;
    y[2] = -x4 + x5;
    y[3] = s3*x7 + x6;
    y[4] = c3*x7 - x8;
    y[5] = td3 - x9;
    y[6] = c1*tdd2 + c2*s1*tdd3 - td1*x4 + td1*x5 - x3*x4;
    y[7] = -s2*tdd3 - td2*x1 + tdd1;
    y[8] = c1*c2*tdd3 - s1*tdd2 - td1*x0 - td1*x2 - x0*x3;
    y[9] = c2*s3*tdd1 + c3*tdd2 + c3*x10 - td3*x8 - x8*x9;
    y[10] = c2*c3*tdd1 - s3*tdd2 - s3*x10 - td3*x6 - x6*x9;
    y[11] = -s2*tdd1 - td2*x7 + tdd3;
}

void ak_anchor_body231(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s1*td2;
    const double x1 = c2*td3;
    const double x2 = c1*x1;
    const double x3 = s2*td3;
    const double x4 = c1*td2;
    const double x5 = s1*x1;
    const double x6 = s2*td1;
    const double x7 = s3*td2;
    const double x8 = c2*td1;
    const double x9 = c2*tdd3;
    const double x10 = c2*tdd1;
    const double x11 = c3*td2;
    const double x12 = td1*x1;
    y[0] = x0 + x2;
    y[1] = td1 + x3;
    y[2] = x4 - x5;
    y[3] = td3 + x6;
    y[4] = c3*x8 + x7;
    y[5] = c3*td2 - s3*x8;
    y[6] = c1*x9 + s1*tdd2 + td1*x4 - td1*x5 - x3*x4;
    y[7] = s2*tdd3 + td2*x1 + tdd1;
    y[8] = c1*tdd2 + s1*s2*td2*td3 - s1*x9 - td1*x0 - td1*x2;
    y[9] = s2*tdd1 + td2*x8 + tdd3;
    y[10] = c3*x10 + s3*tdd2 - s3*x12 + td3*x11 - x11*x6;
    y[11] = c3*tdd2 - c3*x12 + s2*s3*td1*td2 - s3*x10 - td3*x7;
}

void ak_anchor_body312(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c1*td2;
    const double x1 = c2*td3;
    const double x2 = s1*x1;
    const double x3 = s1*td2;
    const double x4 = c1*x1;
    const double x5 = s2*td3;
    const double x6 = c2*td1;
    const double x7 = s2*td1;
    const double x8 = s3*td2;
    const double x9 = c2*tdd3;
    const double x10 = c2*tdd1;
    const double x11 = td1*x1;
    const double x12 = c3*td2;
    y[0] = x0 - x2;
    y[1] = x3 + x4;
    y[2] = td1 + x5;
    y[3] = c3*td2 - s3*x6;
    y[4] = td3 + x7;
    y[5] = c3*x6 + x8;
    y[6] = c1*tdd2 + s1*s2*td2*td3 - s1*x9 - td1*x3 - td1*x4;
    y[7] = c1*x9 + s1*tdd2 + td1*x0 - td1*x2 - x0*x5;
    y[8] = s2*tdd3 + td2*x1 + tdd1;
    y[9] = c3*tdd2 - c3*x11 + s2*s3*td1*td2 - s3*x10 - td3*x8;
    y[10] = s2*tdd1 + td2*x6 + tdd3;
    y[11] = c3*x10 + s3*tdd2 - s3*x11 + td3*x12 - x12*x7;
}

void ak_anchor_body321(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s1*td2;
    const double x1 = c2*td3;
    const double x2 = c1*x1;
    const double x3 = c1*td2;
    const double x4 = s1*x1;
    const double x5 = s2*td3;
    const double x6 = s2*td1;
    const double x7 = c3*td2;
    const double x8 = c2*td1;
    const double x9 = s3*td2;
    const double x10 = td1*x1;
    y[0] = -x0 + x2;
    y[1] = x3 + x4;
    y[2] = td1 - x5;
    y[3] = td3 - x6;
    y[4] = s3*x8 + x7;
    y[5] = c3*x8 - x9;
    y[6] = c1*c2*tdd3 - s1*tdd2 - td1*x3 - td1*x4 - x3*x5;
    y[7] = c1*tdd2 + c2*s1*tdd3 - td1*x0 + td1*x2 - x0*x5;
    y[8] = -s2*tdd3 - td2*x1 + tdd1;
    y[9] = -s2*tdd1 - td2*x8 + tdd3;
    y[10] = c2*s3*tdd1 + c3*tdd2 + c3*x10 - td3*x9 - x6*x9;
    y[11] = c2*c3*tdd1 - s3*tdd2 - s3*x10 - td3*x7 - x6*x7;
}

void ak_anchor_body121(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c2*td3;
    const double x1 = c1*td2;
    const double x2 = s2*td3;
    const double x3 = s1*x2;
    const double x4 = c1*x2;
    const double x5 = c2*td1;
    const double x6 = c3*td2;
    const double x7 = s2*td1;
    const double x8 = s3*td2;
    const double x9 = s2*tdd3;
    const double x10 = s1*td2;
    const double x11 = td1*x2;
    y[0] = td1 + x0;
    y[1] = x1 + x3;
    y[2] = s1*td2 - x4;
    y[3] = td3 + x5;
    y[4] = s3*x7 + x6;
    y[5] = c3*x7 - x8;
    y[6] = c2*tdd3 - td2*x2 + tdd1;
    y[7] = c1*tdd2 + s1*x9 - td1*x10 + td1*x4 + x0*x10;
    y[8] = -c1*x9 + s1*tdd2 + td1*x1 + td1*x3 - x0*x1;
    y[9] = c2*tdd1 - td2*x7 + tdd3;
    y[10] = c3*tdd2 + c3*x11 + s2*s3*tdd1 - td3*x8 + x5*x8;
    y[11] = c2*c3*td1*td2 + c3*s2*tdd1 - s3*tdd2 - s3*x11 - td3*x6;
}

void ak_anchor_body131(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c2*td3;
    const double x1 = s1*td2;
    const double x2 = s2*td3;
    const double x3 = c1*x2;
    const double x4 = c1*td2;
    const double x5 = s1*x2;
    const double x6 = c2*td1;
    const double x7 = s2*td1;
    const double x8 = c3*td2;
    const double x9 = s2*tdd1;
    const double x10 = td1*x2;
    const double x11 = s3*td2;
    y[0] = td1 + x0;
    y[1] = -x1 + x3;
    y[2] = x4 + x5;
    y[3] = td3 + x6;
    y[4] = -c3*x7 + s3*td2;
    y[5] = s3*x7 + x8;
    y[6] = c2*tdd3 - td2*x2 + tdd1;
    y[7] = c1*c2*td2*td3 + c1*s2*tdd3 - s1*tdd2 - td1*x4 - td1*x5;
    y[8] = c1*tdd2 + s1*s2*tdd3 - td1*x1 + td1*x3 + x0*x1;
    y[9] = c2*tdd1 - td2*x7 + tdd3;
    y[10] = -c3*x9 + s3*tdd2 + s3*x10 + td3*x8 - x6*x8;
    y[11] = c3*tdd2 + c3*x10 + s3*x9 - td3*x11 + x11*x6;
}

void ak_anchor_body212(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c1*td2;
    const double x1 = s2*td3;
    const double x2 = s1*x1;
    const double x3 = c2*td3;
    const double x4 = s1*td2;
    const double x5 = c1*x1;
    const double x6 = c3*td2;
    const double x7 = s2*td1;
    const double x8 = c2*td1;
    const double x9 = s2*tdd1;
    const double x10 = s3*td2;
    const double x11 = td1*x1;
    y[0] = x0 + x2;
    y[1] = td1 + x3;
    y[2] = -x4 + x5;
    y[3] = s3*x7 + x6;
    y[4] = td3 + x8;
    y[5] = -c3*x7 + s3*td2;
    y[6] = c1*tdd2 + s1*s2*tdd3 - td1*x4 + td1*x5 + x3*x4;
    y[7] = c2*tdd3 - td2*x1 + tdd1;
    y[8] = c1*c2*td2*td3 + c1*s2*tdd3 - s1*tdd2 - td1*x0 - td1*x2;
    y[9] = c3*tdd2 + c3*x11 + s3*x9 - td3*x10 + x10*x8;
    y[10] = c2*tdd1 - td2*x7 + tdd3;
    y[11] = -c3*x9 + s3*tdd2 + s3*x11 + td3*x6 - x6*x8;
}

void ak_anchor_body232(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s2*td3;
    const double x1 = c1*x0;
    const double x2 = c2*td3;
    const double x3 = c1*td2;
    const double x4 = s1*x0;
    const double x5 = s3*td2;
    const double x6 = s2*td1;
    const double x7 = c2*td1;
    const double x8 = c3*td2;
    const double x9 = s2*tdd3;
    const double x10 = s1*td2;
    const double x11 = td1*x0;
    y[0] = s1*td2 - x1;
    y[1] = td1 + x2;
    y[2] = x3 + x4;
    y[3] = c3*x6 - x5;
    y[4] = td3 + x7;
    y[5] = s3*x6 + x8;
    y[6] = -c1*x9 + s1*tdd2 + td1*x3 + td1*x4 - x2*x3;
    y[7] = c2*tdd3 - td2*x0 + tdd1;
    y[8] = c1*tdd2 + s1*x9 + td1*x1 - td1*x10 + x10*x2;
    y[9] = c2*c3*td1*td2 + c3*s2*tdd1 - s3*tdd2 - s3*x11 - td3*x8;
    y[10] = c2*tdd1 - td2*x6 + tdd3;
    y[11] = c3*tdd2 + c3*x11 + s2*s3*tdd1 - td3*x5 + x5*x7;
}

void ak_anchor_body313(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c1*td2;
    const double x1 = s2*td3;
    const double x2 = s1*x1;
    const double x3 = c1*x1;
    const double x4 = c2*td3;
    const double x5 = c3*td2;
    const double x6 = s2*td1;
    const double x7 = s3*td2;
    const double x8 = c2*td1;
    const double x9 = s2*tdd3;
    const double x10 = s1*td2;
    const double x11 = td1*x1;
    y[0] = x0 + x2;
    y[1] = s1*td2 - x3;
    y[2] = td1 + x4;
    y[3] = s3*x6 + x5;
    y[4] = c3*x6 - x7;
    y[5] = td3 + x8;
    y[6] = c1*tdd2 + s1*x9 - td1*x10 + td1*x3 + x10*x4;
    y[7] = -c1*x9 + s1*tdd2 + td1*x0 + td1*x2 - x0*x4;
    y[8] = c2*tdd3 - td2*x1 + tdd1;
    y[9] = c3*tdd2 + c3*x11 + s2*s3*tdd1 - td3*x7 + x7*x8;
    y[10] = c2*c3*td1*td2 + c3*s2*tdd1 - s3*tdd2 - s3*x11 - td3*x5;
    y[11] = c2*tdd1 - td2*x6 + tdd3;
}

void ak_anchor_body323(const double theta[3], const double theta_dot[3],
                       const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s1*td2;
    const double x1 = s2*td3;
    const double x2 = c1*x1;
    const double x3 = c1*td2;
    const double x4 = s1*x1;
    const double x5 = c2*td3;
    const double x6 = s2*td1;
    const double x7 = c3*td2;
    const double x8 = c2*td1;
    const double x9 = s2*tdd1;
    const double x10 = td1*x1;
    const double x11 = s3*td2;
    y[0] = -x0 + x2;
    y[1] = x3 + x4;
    y[2] = td1 + x5;
    y[3] = -c3*x6 + s3*td2;
    y[4] = s3*x6 + x7;
    y[5] = td3 + x8;
    y[6] = c1*c2*td2*td3 + c1*s2*tdd3 - s1*tdd2 - td1*x3 - td1*x4;
    y[7] = c1*tdd2 + s1*s2*tdd3 - td1*x0 + td1*x2 + x0*x5;
    y[8] = c2*tdd3 - td2*x1 + tdd1;
    y[9] = -c3*x9 + s3*tdd2 + s3*x10 + td3*x7 - x7*x8;
    y[10] = c3*tdd2 + c3*x10 + s3*x9 - td3*x11 + x11*x8;
    y[11] = c2*tdd1 - td2*x6 + tdd3;
}

void ak_anchor_space123(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s3*td2;
    const double x1 = c2*td1;
    const double x2 = c3*x1;
    const double x3 = c3*td2;
    const double x4 = s3*x1;
    const double x5 = s2*td1;
    const double x6 = s2*td3;
    const double x7 = c1*td2;
    const double x8 = c2*td3;
    const double x9 = s1*td2;
    const double x10 = td3*x1;
    y[0] = -x0 + x2;
    y[1] = x3 + x4;
    y[2] = td3 - x5;
    y[3] = td1 - x6;
    y[4] = s1*x8 + x7;
    y[5] = c1*x8 - x9;
    y[6] = c2*c3*tdd1 - s3*tdd2 - td3*x3 - td3*x4 - x3*x5;
    y[7] = c2*s3*tdd1 + c3*tdd2 - td3*x0 + td3*x2 - x0*x5;
    y[8] = -s2*tdd1 - td2*x1 + tdd3;
    y[9] = -s2*tdd3 - td2*x8 + tdd1;
    y[10] = c1*tdd2 + c1*x10 + c2*s1*tdd3 - td1*x9 - x6*x9;
    y[11] = c1*c2*tdd3 - s1*tdd2 - s1*x10 - td1*x7 - x6*x7;
}

void ak_anchor_space132(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s3*td2;
    const double x1 = c2*td1;
    const double x2 = c3*x1;
    const double x3 = s2*td1;
    const double x4 = s3*x1;
    const double x5 = s2*td3;
    const double x6 = s1*td2;
    const double x7 = c2*td3;
    const double x8 = c1*td2;
    const double x9 = c2*tdd1;
    const double x10 = c3*td2;
    const double x11 = c2*tdd3;
    const double x12 = td3*x1;
    y[0] = x0 + x2;
    y[1] = td3 + x3;
    y[2] = c3*td2 - x4;
    y[3] = td1 + x5;
    y[4] = c1*x7 + x6;
    y[5] = -s1*x7 + x8;
    y[6] = c3*x9 + s3*tdd2 + td3*x10 - td3*x4 - x10*x3;
    y[7] = s2*tdd1 + td2*x1 + tdd3;
    y[8] = c3*tdd2 + s2*s3*td1*td2 - s3*x9 - td3*x0 - td3*x2;
    y[9] = s2*tdd3 + td2*x7 + tdd1;
    y[10] = c1*x11 + s1*tdd2 - s1*x12 + td1*x8 - x5*x8;
    y[11] = c1*tdd2 - c1*x12 + s1*s2*td2*td3 - s1*x11 - td1*x6;
}

void ak_anchor_space213(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c2*td1;
    const double x1 = s3*x0;
    const double x2 = s3*td2;
    const double x3 = c3*x0;
    const double x4 = s2*td1;
    const double x5 = c1*td2;
    const double x6 = c2*td3;
    const double x7 = s2*td3;
    const double x8 = s1*td2;
    const double x9 = c2*tdd1;
    const double x10 = c3*td2;
    const double x11 = c2*tdd3;
    const double x12 = td3*x0;
    y[0] = c3*td2 - x1;
    y[1] = x2 + x3;
    y[2] = td3 + x4;
    y[3] = -s1*x6 + x5;
    y[4] = td1 + x7;
    y[5] = c1*x6 + x8;
    y[6] = c3*tdd2 + s2*s3*td1*td2 - s3*x9 - td3*x2 - td3*x3;
    y[7] = c3*x9 + s3*tdd2 - td3*x1 + td3*x10 - x10*x4;
    y[8] = s2*tdd1 + td2*x0 + tdd3;
    y[9] = c1*tdd2 - c1*x12 + s1*s2*td2*td3 - s1*x11 - td1*x8;
    y[10] = s2*tdd3 + td2*x6 + tdd1;
    y[11] = c1*x11 + s1*tdd2 - s1*x12 + td1*x5 - x5*x7;
}

void ak_anchor_space231(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s2*td1;
    const double x1 = s3*td2;
    const double x2 = c2*td1;
    const double x3 = c3*x2;
    const double x4 = c3*td2;
    const double x5 = s3*x2;
    const double x6 = s1*td2;
    const double x7 = c2*td3;
    const double x8 = s2*td3;
    const double x9 = c1*td2;
    const double x10 = td3*x2;
    y[0] = td3 - x0;
    y[1] = -x1 + x3;
    y[2] = x4 + x5;
    y[3] = c1*x7 - x6;
    y[4] = td1 - x8;
    y[5] = s1*x7 + x9;
    y[6] = -s2*tdd1 - td2*x2 + tdd3;
    y[7] = c2*c3*tdd1 - s3*tdd2 - td3*x4 - td3*x5 - x0*x4;
    y[8] = c2*s3*tdd1 + c3*tdd2 - td3*x1 + td3*x3 - x0*x1;
    y[9] = c1*c2*tdd3 - s1*tdd2 - s1*x10 - td1*x9 - x8*x9;
    y[10] = -s2*tdd3 - td2*x7 + tdd1;
    y[11] = c1*tdd2 + c1*x10 + c2*s1*tdd3 - td1*x6 - x6*x8;
}

void ak_anchor_space312(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c3*td2;
    const double x1 = c2*td1;
    const double x2 = s3*x1;
    const double x3 = s2*td1;
    const double x4 = s3*td2;
    const double x5 = c3*x1;
    const double x6 = c1*td2;
    const double x7 = c2*td3;
    const double x8 = s1*td2;
    const double x9 = s2*td3;
    const double x10 = td3*x1;
    y[0] = x0 + x2;
    y[1] = td3 - x3;
    y[2] = -x4 + x5;
    y[3] = s1*x7 + x6;
    y[4] = c1*x7 - x8;
    y[5] = td1 - x9;
    y[6] = c2*s3*tdd1 + c3*tdd2 - td3*x4 + td3*x5 - x3*x4;
    y[7] = -s2*tdd1 - td2*x1 + tdd3;
    y[8] = c2*c3*tdd1 - s3*tdd2 - td3*x0 - td3*x2 - x0*x3;
    y[9] = c1*tdd2 + c1*x10 + c2*s1*tdd3 - td1*x8 - x8*x9;
    y[10] = c1*c2*tdd3 - s1*tdd2 - s1*x10 - td1*x6 - x6*x9;
    y[11] = -s2*tdd3 - td2*x7 + tdd1;
}

void ak_anchor_space321(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s2*td1;
    const double x1 = c2*td1;
    const double x2 = s3*x1;
    const double x3 = s3*td2;
    const double x4 = c3*x1;
    const double x5 = s1*td2;
    const double x6 = c2*td3;
    const double x7 = c1*td2;
    const double x8 = s2*td3;
    const double x9 = c2*tdd1;
    const double x10 = c3*td2;
    const double x11 = c2*tdd3;
    const double x12 = td3*x1;
    y[0] = td3 + x0;
    y[1] = c3*td2 - x2;
    y[2] = x3 + x4;
    y[3] = c1*x6 + x5;
    y[4] = -s1*x6 + x7;
    y[5] = td1 + x8;
    y[6] = s2*tdd1 + td2*x1 + tdd3;
    y[7] = c3*tdd2 + s2*s3*td1*td2 - s3*x9 - td3*x3 - td3*x4;
    y[8] = c3*x9 + s3*tdd2 + td3*x10 - td3*x2 - x0*x10;
    y[9] = c1*x11 + s1*tdd2 - s1*x12 + td1*x7 - x7*x8;
    y[10] = c1*tdd2 - c1*x12 + s1*s2*td2*td3 - s1*x11 - td1*x5;
    y[11] = s2*tdd3 + td2*x6 + tdd1;
}

void ak_anchor_space121(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c2*td1;
    const double x1 = c3*td2;
    const double x2 = s2*td1;
    const double x3 = s3*x2;
    const double x4 = c3*x2;
    const double x5 = c2*td3;
    const double x6 = c1*td2;
    const double x7 = s2*td3;
    const double x8 = s1*td2;
    const double x9 = s2*tdd1;
    const double x10 = s3*td2;
    const double x11 = td3*x2;
    y[0] = td3 + x0;
    y[1] = x1 + x3;
    y[2] = s3*td2 - x4;
    y[3] = td1 + x5;
    y[4] = s1*x7 + x6;
    y[5] = c1*x7 - x8;
    y[6] = c2*tdd1 - td2*x2 + tdd3;
    y[7] = c3*tdd2 + s3*x9 - td3*x10 + td3*x4 + x0*x10;
    y[8] = -c3*x9 + s3*tdd2 + td3*x1 + td3*x3 - x0*x1;
    y[9] = c2*tdd3 - td2*x7 + tdd1;
    y[10] = c1*tdd2 + c1*x11 + s1*s2*tdd3 - td1*x8 + x5*x8;
    y[11] = c1*c2*td2*td3 + c1*s2*tdd3 - s1*tdd2 - s1*x11 - td1*x6;
}

void ak_anchor_space131(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c2*td1;
    const double x1 = s3*td2;
    const double x2 = s2*td1;
    const double x3 = c3*x2;
    const double x4 = c3*td2;
    const double x5 = s3*x2;
    const double x6 = c2*td3;
    const double x7 = s2*td3;
    const double x8 = c1*td2;
    const double x9 = s2*tdd3;
    const double x10 = td3*x2;
    const double x11 = s1*td2;
    y[0] = td3 + x0;
    y[1] = -x1 + x3;
    y[2] = x4 + x5;
    y[3] = td1 + x6;
    y[4] = -c1*x7 + s1*td2;
    y[5] = s1*x7 + x8;
    y[6] = c2*tdd1 - td2*x2 + tdd3;
    y[7] = c2*c3*td1*td2 + c3*s2*tdd1 - s3*tdd2 - td3*x4 - td3*x5;
    y[8] = c3*tdd2 + s2*s3*tdd1 - td3*x1 + td3*x3 + x0*x1;
    y[9] = c2*tdd3 - td2*x7 + tdd1;
    y[10] = -c1*x9 + s1*tdd2 + s1*x10 + td1*x8 - x6*x8;
    y[11] = c1*tdd2 + c1*x10 + s1*x9 - td1*x11 + x11*x6;
}

void ak_anchor_space212(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c3*td2;
    const double x1 = s2*td1;
    const double x2 = s3*x1;
    const double x3 = c2*td1;
    const double x4 = s3*td2;
    const double x5 = c3*x1;
    const double x6 = c1*td2;
    const double x7 = s2*td3;
    const double x8 = c2*td3;
    const double x9 = s2*tdd3;
    const double x10 = s1*td2;
    const double x11 = td3*x1;
    y[0] = x0 + x2;
    y[1] = td3 + x3;
    y[2] = -x4 + x5;
    y[3] = s1*x7 + x6;
    y[4] = td1 + x8;
    y[5] = -c1*x7 + s1*td2;
    y[6] = c3*tdd2 + s2*s3*tdd1 - td3*x4 + td3*x5 + x3*x4;
    y[7] = c2*tdd1 - td2*x1 + tdd3;
    y[8] = c2*c3*td1*td2 + c3*s2*tdd1 - s3*tdd2 - td3*x0 - td3*x2;
    y[9] = c1*tdd2 + c1*x11 + s1*x9 - td1*x10 + x10*x8;
    y[10] = c2*tdd3 - td2*x7 + tdd1;
    y[11] = -c1*x9 + s1*tdd2 + s1*x11 + td1*x6 - x6*x8;
}

void ak_anchor_space232(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s2*td1;
    const double x1 = c3*x0;
    const double x2 = c2*td1;
    const double x3 = c3*td2;
    const double x4 = s3*x0;
    const double x5 = s1*td2;
    const double x6 = s2*td3;
    const double x7 = c2*td3;
    const double x8 = c1*td2;
    const double x9 = s2*tdd1;
    const double x10 = s3*td2;
    const double x11 = td3*x0;
    y[0] = s3*td2 - x1;
    y[1] = td3 + x2;
    y[2] = x3 + x4;
    y[3] = c1*x6 - x5;
    y[4] = td1 + x7;
    y[5] = s1*x6 + x8;
    y[6] = -c3*x9 + s3*tdd2 + td3*x3 + td3*x4 - x2*x3;
    y[7] = c2*tdd1 - td2*x0 + tdd3;
    y[8] = c3*tdd2 + s3*x9 + td3*x1 - td3*x10 + x10*x2;
    y[9] = c1*c2*td2*td3 + c1*s2*tdd3 - s1*tdd2 - s1*x11 - td1*x8;
    y[10] = c2*tdd3 - td2*x6 + tdd1;
    y[11] = c1*tdd2 + c1*x11 + s1*s2*tdd3 - td1*x5 + x5*x7;
}

void ak_anchor_space313(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = c3*td2;
    const double x1 = s2*td1;
    const double x2 = s3*x1;
    const double x3 = c3*x1;
    const double x4 = c2*td1;
    const double x5 = c1*td2;
    const double x6 = s2*td3;
    const double x7 = s1*td2;
    const double x8 = c2*td3;
    const double x9 = s2*tdd1;
    const double x10 = s3*td2;
    const double x11 = td3*x1;
    y[0] = x0 + x2;
    y[1] = s3*td2 - x3;
    y[2] = td3 + x4;
    y[3] = s1*x6 + x5;
    y[4] = c1*x6 - x7;
    y[5] = td1 + x8;
    y[6] = c3*tdd2 + s3*x9 - td3*x10 + td3*x3 + x10*x4;
    y[7] = -c3*x9 + s3*tdd2 + td3*x0 + td3*x2 - x0*x4;
    y[8] = c2*tdd1 - td2*x1 + tdd3;
    y[9] = c1*tdd2 + c1*x11 + s1*s2*tdd3 - td1*x7 + x7*x8;
    y[10] = c1*c2*td2*td3 + c1*s2*tdd3 - s1*tdd2 - s1*x11 - td1*x5;
    y[11] = c2*tdd3 - td2*x6 + tdd1;
}

void ak_anchor_space323(const double theta[3], const double theta_dot[3],
                        const double theta_ddot[3], double y[12]) {
    const double s1 = sin(theta[0]), c1 = cos(theta[0]);
    const double s2 = sin(theta[1]), c2 = cos(theta[1]);
    const double s3 = sin(theta[2]), c3 = cos(theta[2]);
    const double td1 = theta_dot[0], tdd1 = theta_ddot[0];
    const double td2 = theta_dot[1], tdd2 = theta_ddot[1];
    const double td3 = theta_dot[2], tdd3 = theta_ddot[2];
    const double x0 = s3*td2;
    const double x1 = s2*td1;
    const double x2 = c3*x1;
    const double x3 = c3*td2;
    const double x4 = s3*x1;
    const double x5 = c2*td1;
    const double x6 = s2*td3;
    const double x7 = c1*td2;
    const double x8 = c2*td3;
    const double x9 = s2*tdd3;
    const double x10 = td3*x1;
    const double x11 = s1*td2;
    y[0] = -x0 + x2;
    y[1] = x3 + x4;
    y[2] = td3 + x5;
    y[3] = -c1*x6 + s1*td2;
    y[4] = s1*x6 + x7;
    y[5] = td1 + x8;
    y[6] = c2*c3*td1*td2 + c3*s2*tdd1 - s3*tdd2 - td3*x3 - td3*x4;
    y[7] = c3*tdd2 + s2*s3*tdd1 - td3*x0 + td3*x2 + x0*x5;
    y[8] = c2*tdd1 - td2*x1 + tdd3;
    y[9] = -c1*x9 + s1*tdd2 + s1*x10 + td1*x7 - x7*x8;
    y[10] = c1*tdd2 + c1*x10 + s1*x9 - td1*x11 + x11*x8;
    y[11] = c2*tdd3 - td2*x6 + tdd1;
}

ak_anchor_kernel *const AK_ANCHORS[24] = {
    ak_anchor_body123,
    ak_anchor_body132,
    ak_anchor_body213,
    ak_anchor_body231,
    ak_anchor_body312,
    ak_anchor_body321,
    ak_anchor_body121,
    ak_anchor_body131,
    ak_anchor_body212,
    ak_anchor_body232,
    ak_anchor_body313,
    ak_anchor_body323,
    ak_anchor_space123,
    ak_anchor_space132,
    ak_anchor_space213,
    ak_anchor_space231,
    ak_anchor_space312,
    ak_anchor_space321,
    ak_anchor_space121,
    ak_anchor_space131,
    ak_anchor_space212,
    ak_anchor_space232,
    ak_anchor_space313,
    ak_anchor_space323,
};
