/* Benchmark: the general core against the hand-written 1-2-3 core, nanoseconds per evaluation of
 * omega and alpha in both frames. Prints the median of 15 rounds of 200 000 evaluations each (the
 * same 1024 random states cycled), and the median of the per-round ratios. Bounded: a few seconds.
 *     build/bench_sequences        (after bash scripts/build.sh; Release flags) */
#include "kinematics_123.h"
#include "kinematics_general.h"
#include "kinematics_general_kernel.h"
#include "sequences.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { STATES = 1024, EVALUATIONS = 200000, ROUNDS = 15 };

static double now(void) {
    struct timespec t;
    timespec_get(&t, TIME_UTC); /* C11, also on MSVC */
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int by_value(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *values, int count) {
    qsort(values, (size_t)count, sizeof(double), by_value);
    return values[count / 2];
}

static double states[STATES][9];
static volatile double sink;

/* ns per evaluation; sequence NULL: the hand-written 1-2-3 core. */
static double one_round(const ak_sequence *sequence) {
    double out[12], sum = 0.0;
    const double start = now();
    for (int n = 0; n < EVALUATIONS; n++) {
        const double *x = states[n % STATES];
        if (sequence) {
            ak_general_angular_kinematics(sequence, x, x + 3, x + 6, out, out + 3, out + 6, out + 9);
        } else {
            ak_angular_kinematics_123(x, x + 3, x + 6, out, out + 3, out + 6, out + 9);
        }
        sum += out[n % 12];
    }
    sink = sum;
    return (now() - start) * 1e9 / EVALUATIONS;
}

int main(void) {
    srand(20261121);
    for (int n = 0; n < STATES; n++) {
        for (int k = 0; k < 9; k++) {
            states[n][k] = 4.0 * rand() / (double)RAND_MAX - 2.0;
        }
    }
    const int chosen[3] = {0, 5, 22}; /* body123, body321, space313 */
    double hand[ROUNDS], general[3][ROUNDS], ratio[ROUNDS];
    for (int r = 0; r < ROUNDS; r++) {
        hand[r] = one_round(NULL);
        for (int s = 0; s < 3; s++) {
            general[s][r] = one_round(&AK_SEQUENCES[chosen[s]]);
        }
        ratio[r] = general[0][r] / hand[r];
    }
    printf("ns per evaluation (median of %d rounds of %d):\n", ROUNDS, EVALUATIONS);
    printf("  ak_angular_kinematics_123 (hand-written)  %7.1f\n", median(hand, ROUNDS));
    for (int s = 0; s < 3; s++) {
        printf("  ak_general_angular_kinematics %-10s %7.1f\n", AK_SEQUENCES[chosen[s]].name,
               median(general[s], ROUNDS));
    }
    printf("  ratio general body123 / hand-written: %.2f (median of per-round ratios)\n",
           median(ratio, ROUNDS));
    return 0;
}
