/* Three atan2 at once, the angle extraction's shape (fmu_src/core/attitude.c): ak_atan2 called
 * three times, ak_atan2_three, and the C library's atan2 three times, alternately in one process.
 * The arguments are 4096 triples of random angles in [-pi, pi) as (r sin, r cos), r in [0.5, 2),
 * from a fixed generator. Two loops of each: "independent" (the triples do not depend on each
 * other, the processor may overlap them) and "chained" (each triple's y waits for the previous
 * results, as a step waits for the last one). Figures: medians of the repeats, thread CPU time
 * per triple.
 *   build/bench/bench_atan2 [--calls N] [--repeats R]
 * It fails (exit 1) unless ak_atan2_three gives ak_atan2's bits on every triple. */
#define _POSIX_C_SOURCE 200809L
#include "bench_timing.h"
#include "elementary.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { N_TRIPLES = 4096, MAX_REPEATS = 99, N_WAYS = 3 };

typedef struct {
    double y[N_TRIPLES][3], x[N_TRIPLES][3];
} triples;

/* A volatile sink: the loops' results are used, so the compiler keeps them. */
static volatile double sink;

static void three_scalar(const double y[3], const double x[3], double out[3]) {
    out[0] = ak_atan2(y[0], x[0]);
    out[1] = ak_atan2(y[1], x[1]);
    out[2] = ak_atan2(y[2], x[2]);
}

static void three_libm(const double y[3], const double x[3], double out[3]) {
    out[0] = atan2(y[0], x[0]);
    out[1] = atan2(y[1], x[1]);
    out[2] = atan2(y[2], x[2]);
}

static const char *const NAMES[N_WAYS] = {"ak_atan2 x 3", "ak_atan2_three",
                                          "C library's atan2 x 3"};

/* ns per triple. Chained: y + 0 * (the previous sum) is y (the sum is finite), but waits for it.
 * The way is a constant at each call site (the switch), so LTO inlines as in the models. */
static double time_way(int way, const triples *in, long rounds, int chained) {
    double acc = 0.0, previous = 0.0;
    const double start = ak_bench_now_ns();
    for (long k = 0; k < rounds; k++) {
        for (int i = 0; i < N_TRIPLES; i++) {
            double y[3], out[3];
            for (int c = 0; c < 3; c++) {
                y[c] = chained ? in->y[i][c] + 0.0 * previous : in->y[i][c];
            }
            switch (way) {
            case 0: three_scalar(y, in->x[i], out); break;
            case 1: ak_atan2_three(y, in->x[i], out); break;
            default: three_libm(y, in->x[i], out); break;
            }
            previous = out[0] + out[1] + out[2];
            acc += previous;
        }
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = acc;
    return elapsed / ((double)rounds * N_TRIPLES);
}

int main(int argc, char **argv) {
    double calls = 1e7;
    int repeats = 5;
    ak_bench_calls_and_repeats(argc, argv, &calls, &repeats);
    if (repeats < 1 || repeats > MAX_REPEATS || !(calls >= N_TRIPLES)) {
        fprintf(stderr, "usage: bench_atan2 [--calls N >= %d] [--repeats 1..%d] (N triples)\n",
                N_TRIPLES, MAX_REPEATS);
        return 2;
    }
    static triples in;
    uint64_t state = 1u;
    for (int i = 0; i < N_TRIPLES; i++) {
        for (int c = 0; c < 3; c++) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const double unit = (double)(state >> 11) / 9007199254740992.0; /* [0, 1) */
            const double angle = (unit - 0.5) * 2.0 * 3.14159265358979323846;
            const double radius = 0.5 + 1.5 * (double)((state >> 20) & 0xFFFF) / 65536.0;
            in.y[i][c] = radius * sin(angle);
            in.x[i][c] = radius * cos(angle);
        }
    }
    for (int i = 0; i < N_TRIPLES; i++) {
        double one[3], three[3];
        three_scalar(in.y[i], in.x[i], one);
        ak_atan2_three(in.y[i], in.x[i], three);
        if (memcmp(one, three, sizeof one) != 0) {
            fprintf(stderr, "bench_atan2: ak_atan2_three differs from ak_atan2 at triple %d\n", i);
            return 1;
        }
    }
    const long rounds = (long)(calls / N_TRIPLES);
    double ns[2][N_WAYS][MAX_REPEATS], ratio[2][2][MAX_REPEATS];
    for (int r = 0; r < repeats; r++) {
        for (int chained = 0; chained < 2; chained++) {
            for (int way = 0; way < N_WAYS; way++) {
                ns[chained][way][r] = time_way(way, &in, rounds, chained);
            }
            ratio[chained][0][r] = ns[chained][1][r] / ns[chained][0][r];
            ratio[chained][1][r] = ns[chained][1][r] / ns[chained][2][r];
        }
    }
    printf("| three atan2 of random angles | independent ns/triple | chained ns/triple |\n"
           "|---|---:|---:|\n");
    for (int way = 0; way < N_WAYS; way++) {
        printf("| %s | %.2f | %.2f |\n", NAMES[way], ak_bench_median(ns[0][way], repeats),
               ak_bench_median(ns[1][way], repeats));
    }
    printf("\nak_atan2_three / (ak_atan2 x 3): %.3f independent, %.3f chained; / (C library x 3): "
           "%.3f, %.3f (medians of %d alternating repeats)\n",
           ak_bench_median(ratio[0][0], repeats), ak_bench_median(ratio[1][0], repeats),
           ak_bench_median(ratio[0][1], repeats), ak_bench_median(ratio[1][1], repeats), repeats);
    return 0;
}
