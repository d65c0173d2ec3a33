/* The point kinematics core (fmu_src/core/point_kinematics.h) against closed forms of simple
 * motions and, on random inputs, against the other form of the centripetal term
 * (omega (omega . r) - r |omega|^2, in long double), and its tangent against central differences
 * (exact for these polynomials up to roundoff). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "point_kinematics.h"
#include "test_check.h"

static ak_point_outputs run(const double omega[3], const double alpha[3], const double v_O[3],
                            const double a_O[3], const double r[3], const double r_dot[3],
                            const double r_ddot[3], const double g[3]) {
    const ak_point_inputs in = {omega, alpha, v_O, a_O, r, r_dot, r_ddot, g};
    ak_point_outputs out;
    ak_point_kinematics(&in, &out);
    return out;
}

static const double ZERO[3] = {0.0, 0.0, 0.0};

/* A body spinning at w about its third axis, P fixed at (R, 0, 0): v = (0, w R, 0), a = (-w^2 R, 0, 0). */
static void uniform_rotation(void) {
    const double w = 3.0, R = 2.0;
    const double omega[3] = {0.0, 0.0, w}, r[3] = {R, 0.0, 0.0};
    const ak_point_outputs out = run(omega, ZERO, ZERO, ZERO, r, ZERO, ZERO, ZERO);
    ak_check(out.v_P[0] == 0.0 && out.v_P[1] == w * R && out.v_P[2] == 0.0, "uniform: v_P");
    ak_check(out.a_centripetal[0] == -w * w * R && out.a_centripetal[1] == 0.0 &&
                 out.a_centripetal[2] == 0.0, "uniform: a_centripetal = (%g, %g, %g)",
             out.a_centripetal[0], out.a_centripetal[1], out.a_centripetal[2]);
    ak_check(out.a_P[0] == -w * w * R && out.a_coriolis[1] == 0.0, "uniform: a_P");
}

/* P sliding outward at u along the first axis of a body spinning at w about the third:
 * Coriolis 2 w u along the second axis; spin-up alpha about the third: tangential alpha R. */
static void sliding_and_spin_up(void) {
    const double w = 0.5, u = 4.0, a = 0.25, R = 8.0;
    const double omega[3] = {0.0, 0.0, w}, alpha[3] = {0.0, 0.0, a}, r[3] = {R, 0.0, 0.0},
                 r_dot[3] = {u, 0.0, 0.0}, g[3] = {0.0, 0.0, -9.81};
    const ak_point_outputs out = run(omega, alpha, ZERO, ZERO, r, r_dot, ZERO, g);
    ak_check(out.a_coriolis[0] == 0.0 && out.a_coriolis[1] == 2.0 * w * u &&
                 out.a_coriolis[2] == 0.0, "sliding: a_coriolis[2] = %g", out.a_coriolis[1]);
    ak_check(out.a_tangential[1] == a * R, "spin-up: a_tangential[2] = %g", out.a_tangential[1]);
    ak_check(out.v_P[0] == u && out.v_P[1] == w * R, "sliding: v_P");
    ak_check(out.a_P[1] == a * R + 2.0 * w * u, "sliding: a_P[2] = %g", out.a_P[1]);
    ak_check(out.specific_force[2] == 9.81, "at rest vertically the accelerometer reads +g up: %g",
             out.specific_force[2]);
}

static uint64_t state = 88172645463325252u;
static double uniform(void) { /* xorshift64, in [-1, 1) */
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (double)(state >> 11) / 4503599627370496.0 - 1.0;
}

static void random_vector(double v[3]) {
    for (int k = 0; k < 3; k++) {
        v[k] = uniform() * pow(10.0, 3.0 * uniform()); /* sizes 1e-3 to 1e3, either sign */
    }
}

static long double norm(const double v[3]) {
    return sqrtl((long double)v[0] * v[0] + (long double)v[1] * v[1] + (long double)v[2] * v[2]);
}

static void random_inputs(void) {
    double worst = 0.0;
    for (int n = 0; n < 100000; n++) {
        double omega[3], alpha[3], v_O[3], a_O[3], r[3], r_dot[3], r_ddot[3], g[3];
        random_vector(omega), random_vector(alpha), random_vector(v_O), random_vector(a_O);
        random_vector(r), random_vector(r_dot), random_vector(r_ddot), random_vector(g);
        const ak_point_outputs out = run(omega, alpha, v_O, a_O, r, r_dot, r_ddot, g);
        long double dot = 0.0L, w2 = 0.0L;
        for (int k = 0; k < 3; k++) {
            dot += (long double)omega[k] * r[k];
            w2 += (long double)omega[k] * omega[k];
        }
        const long double scale = fmaxl(1.0L, norm(omega) * norm(omega) * norm(r));
        for (int k = 0; k < 3; k++) {
            const long double expected = omega[k] * dot - r[k] * w2;
            const double error = (double)(fabsl(out.a_centripetal[k] - expected) / scale);
            worst = fmax(worst, error);
        }
    }
    ak_check(worst <= 1e-15, "random: a_centripetal within %g of omega (omega . r) - r |omega|^2",
             worst);
    printf("a_centripetal on 100000 random inputs: worst error %.3g of |omega|^2 |r|\n", worst);
}

/* The tangent along each input direction against central differences of step h. */
static void tangent(void) {
    double values[24], d[24];
    for (int k = 0; k < 24; k++) {
        values[k] = uniform();
    }
    for (int k = 0; k < 24; k++) {
        for (int m = 0; m < 24; m++) {
            d[m] = m == k ? 1.0 : 0.0;
        }
        const ak_point_inputs in = {&values[0], &values[3], &values[6], &values[9], &values[12],
                                    &values[15], &values[18], &values[21]};
        const ak_point_inputs d_in = {&d[0], &d[3], &d[6], &d[9], &d[12], &d[15], &d[18], &d[21]};
        ak_point_outputs d_out, plus, minus;
        ak_point_kinematics_tangent(&in, &d_in, &d_out);
        const double h = 1e-5, saved = values[k];
        values[k] = saved + h;
        ak_point_kinematics(&in, &plus);
        values[k] = saved - h;
        ak_point_kinematics(&in, &minus);
        values[k] = saved;
        const double *t = (const double *)&d_out, *p = (const double *)&plus,
                     *q = (const double *)&minus;
        for (int i = 0; i < 18; i++) {
            ak_check_close(t[i], (p[i] - q[i]) / (2.0 * h), 1e-9, "tangent: output %d along input %d",
                           i, k);
        }
    }
}

/* The returned flag: true for finite outputs, false when a product overflows (omega x r: 1e400). */
static void overflow_flag(void) {
    const double omega[3] = {1e200, 0.0, 0.0}, r[3] = {0.0, 1e200, 0.0}, small[3] = {1.0, 2.0, 3.0};
    ak_point_outputs out;
    const ak_point_inputs huge = {omega, ZERO, ZERO, ZERO, r, ZERO, ZERO, ZERO};
    const ak_point_inputs fine = {small, small, small, small, small, small, small, small};
    ak_check(!ak_point_kinematics(&huge, &out) && isinf(out.v_P[2]), "overflow: flag false");
    ak_check(ak_point_kinematics(&fine, &out), "finite: flag true");
}

int main(void) {
    overflow_flag();
    uniform_rotation();
    sliding_and_spin_up();
    random_inputs();
    tangent();
    printf("%d checks, %d failed\n", ak_check_count(), ak_check_failures());
    return ak_check_exit_status();
}
