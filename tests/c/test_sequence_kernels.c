/* The generated kernels of kinematics_sequences.c (codegen/sequence_kernels.py) against the
 * general chain kernel they are generated from (ak_chain_angular_kinematics_of_sines), for all 24
 * sequences, output by output and bit for bit: over random inputs (angles of any size, rates and
 * accelerations from 1e-3 to 1e3 of either sign), over inputs with exact zeros (+0 and -0) and
 * exact quarter turns, and over sines that are not those of any angle (the identity is
 * structural: it must not rest on sin^2 + cos^2 = 1). The only difference allowed is the sign of
 * an output that is exactly zero; such outputs are counted and printed. The same for the generated
 * inverse maps (kinematics_rates_sequences.c, both frames) against ak_chain_euler_rates_of_sines:
 * statuses, distances and outputs, also next to the singularity and with overflowing inputs.
 * Usage:
 *   test_sequence_kernels [random inputs per sequence, default 20000] */
#include "kinematics_general.h"
#include "kinematics_general_kernel.h"
#include "sequences.h"
#include "test_check.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t state = 0x9e3779b97f4a7c15u;

/* xorshift64*: the same inputs on every platform (rand() is not). */
static double uniform(double low, double high) {
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    const uint64_t bits = state * 0x2545f4914f6cdd1du;
    return low + (high - low) * ((double)(bits >> 11) * 0x1.0p-53);
}

static double rate(void) {
    const double size = pow(10.0, floor(uniform(-3.0, 4.0)));
    return uniform(-1.0, 1.0) * size;
}

static uint64_t bits_of(double x) {
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    return b;
}

static long compared, zero_sign_differences;

/* One input: the sequence's generated kernel (through the table) against the chain kernel. */
static void compare(int k, const ak_sines *sines, const double td[3], const double tdd[3]) {
    const ak_sequence *seq = &AK_SEQUENCES[k];
    double generated[12], general[12];
    ak_general_angular_kinematics_of_sines(seq, sines, td, tdd, generated, generated + 3,
                                           generated + 6, generated + 9);
    ak_chain_angular_kinematics_of_sines(seq, sines, td, tdd, general, general + 3, general + 6,
                                         general + 9);
    for (int i = 0; i < 12; i++) {
        compared++;
        if (bits_of(generated[i]) == bits_of(general[i])) {
            continue;
        }
        const bool zeros = generated[i] == 0.0 && general[i] == 0.0;
        zero_sign_differences += zeros;
        ak_check(zeros, "%s output %d: generated %a, general %a", seq->name, i, generated[i],
                 general[i]);
    }
}

static void compare_angles(int k, const double theta[3], const double td[3], const double tdd[3]) {
    ak_sines sines;
    ak_angle_sines(theta, &sines);
    compare(k, &sines, td, tdd);
}

static long rates_compared, rates_zero_sign_differences, rates_by_status[4];

/* One input of the inverse map, both frames: the generated kernel between the core's checks
 * (ak_general_euler_rates_of_sines) against the general chain code; the sequence a copy of the
 * table entry every other time (the core finds the kernel from the axes, not the address). */
static void compare_rates(int k, const double theta[3], const ak_sines *sines,
                          const double omega[3], const double omega_dot[3]) {
    const ak_sequence copy = AK_SEQUENCES[k];
    const ak_sequence *seq = (rates_compared & 1) ? &copy : &AK_SEQUENCES[k];
    for (int frame = AK_FRAME_FIXED; frame <= AK_FRAME_BODY; frame++) {
        double generated[12], general[12], d_generated = -1.0, d_general = -2.0;
        for (int i = 0; i < 12; i++) {
            generated[i] = general[i] = 42.0; /* untouched unless written */
        }
        const ak_rates_status s_generated = ak_general_euler_rates_of_sines(
            seq, (ak_frame)frame, theta, sines, omega, omega_dot, 1e-3, generated, generated + 3,
            generated + 6, generated + 9, &d_generated);
        const ak_rates_status s_general = ak_chain_euler_rates_of_sines(
            seq, (ak_frame)frame, theta, sines, omega, omega_dot, 1e-3, general, general + 3,
            general + 6, general + 9, &d_general);
        rates_compared++;
        rates_by_status[s_general]++;
        ak_check(s_generated == s_general, "%s rates: status generated %d, general %d",
                 seq->name, (int)s_generated, (int)s_general);
        ak_check(bits_of(d_generated) == bits_of(d_general), "%s rates: distance %a, %a",
                 seq->name, d_generated, d_general);
        for (int i = 0; i < 12; i++) {
            if (bits_of(generated[i]) == bits_of(general[i])) {
                continue;
            }
            const bool zeros = generated[i] == 0.0 && general[i] == 0.0;
            rates_zero_sign_differences += zeros;
            ak_check(zeros, "%s rates, frame %d, output %d: generated %a, general %a", seq->name,
                     frame, i, generated[i], general[i]);
        }
    }
}

static void compare_rates_angles(int k, const double theta[3], const double omega[3],
                                 const double omega_dot[3]) {
    ak_sines sines;
    ak_angle_sines(theta, &sines);
    compare_rates(k, theta, &sines, omega, omega_dot);
    /* The one-call form: the sines of theta, the same results. */
    double once[12], twice[12], d_once, d_twice;
    const ak_rates_status s_once = ak_general_euler_rates(
        &AK_SEQUENCES[k], AK_FRAME_BODY, theta, omega, omega_dot, 1e-3, once, once + 3, once + 6,
        once + 9, &d_once);
    const ak_rates_status s_twice = ak_general_euler_rates_of_sines(
        &AK_SEQUENCES[k], AK_FRAME_BODY, theta, &sines, omega, omega_dot, 1e-3, twice, twice + 3,
        twice + 6, twice + 9, &d_twice);
    ak_check(s_once == s_twice && (s_once == AK_RATES_SINGULAR || s_once == AK_RATES_OVERFLOW ||
                                   memcmp(once, twice, sizeof once) == 0),
             "%s rates: of theta = of its sines", AK_SEQUENCES[k].name);
}

/* theta2 at or next to the singular angle of the sequence (0 or pi for proper Euler sequences,
 * +-pi/2 for Tait-Bryan ones), a few ulp to 1e-6 away. */
static double near_singular(int k) {
    const double base = AK_SEQUENCES[k].proper_euler ? (uniform(0.0, 2.0) < 1.0 ? 0.0
                                                                                : 3.141592653589793)
                                                     : (uniform(0.0, 2.0) < 1.0 ? 1.5707963267948966
                                                                                : -1.5707963267948966);
    const double offset = uniform(-1.0, 1.0) * pow(10.0, uniform(-17.0, -6.0));
    return base + offset;
}

/* An input component: random, or one of the special values at random. */
static double special(double random_value) {
    static const double SPECIAL[] = {0.0, -0.0, 1.0, -1.0, 1.5707963267948966, 3.141592653589793};
    const double pick = uniform(0.0, 2.0);
    return pick < 1.0 ? random_value : SPECIAL[(int)(pick * 6.0) % 6];
}

int main(int argc, char **argv) {
    const long n = argc > 1 ? atol(argv[1]) : 20000;
    for (int k = 0; k < AK_SEQUENCE_COUNT; k++) {
        for (long i = 0; i < n; i++) {
            double theta[3], td[3], tdd[3];
            for (int j = 0; j < 3; j++) {
                theta[j] = uniform(-20.0, 20.0);
                td[j] = rate();
                tdd[j] = rate();
            }
            compare_angles(k, theta, td, tdd);
            for (int j = 0; j < 3; j++) {
                theta[j] = special(theta[j]);
                td[j] = special(td[j]);
                tdd[j] = special(tdd[j]);
            }
            compare_angles(k, theta, td, tdd);
            ak_sines free_sines; /* any numbers in [-1, 1], not sines of an angle */
            for (int j = 0; j < 3; j++) {
                free_sines.sin[j] = uniform(-1.0, 1.0);
                free_sines.cos[j] = uniform(-1.0, 1.0);
            }
            compare(k, &free_sines, td, tdd);

            double omega[3], omega_dot[3];
            for (int j = 0; j < 3; j++) {
                theta[j] = uniform(-20.0, 20.0);
                omega[j] = rate();
                omega_dot[j] = rate();
            }
            compare_rates_angles(k, theta, omega, omega_dot);
            theta[1] = near_singular(k);
            compare_rates_angles(k, theta, omega, omega_dot);
            for (int j = 0; j < 3; j++) {
                theta[j] = special(theta[j]);
                omega[j] = special(omega[j]);
                omega_dot[j] = special(omega_dot[j]);
            }
            compare_rates_angles(k, theta, omega, omega_dot);
            const double huge[3] = {1e306 * omega[0], -1e306, 1e306 * omega_dot[2]};
            compare_rates_angles(k, theta, huge, omega_dot); /* overflows, or not */
            compare_rates_angles(k, theta, omega, huge);
            compare_rates(k, theta, &free_sines, omega, omega_dot);
        }
        const double zeros[3] = {0.0, 0.0, 0.0}, negative_zeros[3] = {-0.0, -0.0, -0.0};
        compare_angles(k, zeros, zeros, zeros);
        compare_angles(k, negative_zeros, negative_zeros, negative_zeros);
        compare_rates_angles(k, zeros, zeros, zeros);
        compare_rates_angles(k, negative_zeros, negative_zeros, negative_zeros);
    }
    /* Every status met, so that each path of the checks was compared. */
    for (int s = 0; s < 4; s++) {
        ak_check(rates_by_status[s] > 0, "%s: status met", "rates");
    }
    printf("test_sequence_kernels: %ld outputs of the 24 generated kernels compared with the "
           "general kernel: %ld differ, all in the sign of an exact zero; %ld inputs of the 48 "
           "generated inverse maps (ok %ld, near-singular %ld, singular %ld, overflow %ld): %ld "
           "outputs differ, all in the sign of an exact zero; %d checks, %d failed\n",
           compared, zero_sign_differences, rates_compared, rates_by_status[AK_RATES_OK],
           rates_by_status[AK_RATES_NEAR_SINGULAR], rates_by_status[AK_RATES_SINGULAR],
           rates_by_status[AK_RATES_OVERFLOW], rates_zero_sign_differences, ak_check_count(),
           ak_check_failures());
    return ak_check_exit_status();
}
