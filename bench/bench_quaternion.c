/* QuaternionKinematics' FMI 2 cycle beside its floor, timed alternately in one run, repeat after
 * repeat, so that all see the same machine load:
 *   - QuaternionKinematics: fmi2SetReal of the 12 inputs (q, q_dot, q_ddot), fmi2DoStep,
 *     fmi2GetReal of the 32 outputs (build/fmu/binaries/linux64/QuaternionKinematics.so, default
 *     sequence body123);
 *   - the pass-through FMU: the same calls with the same counts (build/passthrough/PassThrough.so:
 *     it sets 12 inputs, value references 0..11, and gets 32 variables, 10..41, each get costing
 *     the same for any value reference): what an importer pays for the calls of any FMU of the
 *     interface;
 *   - the anchor: the hand-written body123 formula on the same rows (bench/quaternion_anchor.c,
 *     frozen).
 * Goal: the cycle at most 1.3 x (pass-through cycle + formula); the ratio quoted is the
 * median of the per-repeat ratios. Two kinds of rows (256 each, cycled; consecutive rows differ in
 * every input, so every step evaluates):
 *   random: q with components in [-1, 1] (|q| from 0.25 on), q_dot in [-5, 5], q_ddot in
 *     [-50, 50], independent at every step;
 *   smooth: a tumbling body sampled every 0.01 s, q(t) = s(t) qa(t) qb(t), two rotations about
 *     fixed axes whose angles run unevenly (phi(t) = 2 w t + 0.7 sin(w t), psi(t) = w t +
 *     0.5 sin(2 w t + 1), w = 2 pi / 2.56 s, so that the 256 rows close on the same attitude)
 *     and |q| = s(t) = 1 + 3e-7 sin(w t + 0.3) drifting from 1 as an integrator's, with the
 *     exact first and second derivatives of q(t).
 * Before timing, every output of the FMU's cycle on every row of both kinds is checked against
 * the anchor (within 1e-12 of the size of its vector), so that both compute the same thing.
 * CPU time of the thread. With AK_BENCH_FIGURES set, appends "qk-fmi2 KIND ratio floor
 * passthrough_ns" (floor: (pass-through + formula) / formula) for bench/run.sh's goals table.
 *
 * Usage: bench_quaternion QK_SO PASSTHROUGH_SO [STEPS [REPEATS [random|smooth|both]]]
 *          (defaults 1e6, 5, both)
 *        bench_quaternion QK_SO PASSTHROUGH_SO STEPS 1 random|smooth quaternion|passthrough|anchor
 *          (one loop, once: for instruction counts under callgrind) */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, dlopen */

#include <dlfcn.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "QuaternionKinematics_variables.h" /* QK_GUID, QK_VR_*, generated */
#include "bench_timing.h"
#include "fmi2FunctionTypes.h"
#include "quaternion_anchor.h"

#define PASSTHROUGH_GUID "{5b2d7a40-3c1e-4f8a-9d6b-0e4f2a7c9b13}"

enum { ROWS = 256, N_IN = 12, N_OUT = 32, MAX_REPEATS = 51 };
_Static_assert((int)N_IN == (int)QK_N_INPUTS && (int)N_OUT == (int)QK_N_OUTPUTS,
               "the model's counts");
static double rows[ROWS][N_IN];
static volatile double sink;

typedef struct {
    const char *name;
    const char *guid;
    fmi2Component c;
    fmi2SetRealTYPE *set_real;
    fmi2GetRealTYPE *get_real;
    fmi2DoStepTYPE *do_step;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2ValueReference outputs[N_OUT]; /* the value references read */
    double time;                        /* the next communication point */
} fmu;

static const double STEP = 0.01;

/* Returns 0, or -1 if two consecutive rows share a value. */
static int check_rows(void) {
    for (int row = 0; row < ROWS; row++) {
        for (int k = 0; k < N_IN; k++) {
            if (rows[row][k] == rows[(row + 1) % ROWS][k]) {
                return -1;
            }
        }
    }
    return 0;
}

static int fill_random_rows(void) {
    uint64_t x = 0x2545F4914F6CDD1Du;
    static const double range[3] = {1.0, 5.0, 50.0};
    for (int row = 0; row < ROWS; row++) {
        double n2;
        do {
            n2 = 0.0;
            for (int k = 0; k < N_IN; k++) {
                x ^= x << 13, x ^= x >> 7, x ^= x << 17;
                const double u = (double)(x >> 11) / 9007199254740992.0; /* [0, 1) */
                rows[row][k] = (2.0 * u - 1.0) * range[k / 4];
                n2 += k < 4 ? rows[row][k] * rows[row][k] : 0.0;
            }
        } while (n2 < 0.0625);
    }
    return check_rows();
}

/* Hamilton product, scalar first. */
static void product(const double a[4], const double b[4], double c[4]) {
    c[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    c[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    c[2] = a[0] * b[2] + a[2] * b[0] + a[3] * b[1] - a[1] * b[3];
    c[3] = a[0] * b[3] + a[3] * b[0] + a[1] * b[2] - a[2] * b[1];
}

/* The rotation by angle(t) about the unit axis and its first two time derivatives, from the
 * angle's: (cos h, sin h axis), h = angle / 2. */
static void axis_rotation(const double axis[3], double angle, double rate, double acceleration,
                          double r[4], double r_dot[4], double r_ddot[4]) {
    const double c = cos(0.5 * angle), s = sin(0.5 * angle), hd = 0.5 * rate,
                 hdd = 0.5 * acceleration;
    r[0] = c, r_dot[0] = -s * hd, r_ddot[0] = -s * hdd - c * hd * hd;
    for (int k = 0; k < 3; k++) {
        r[k + 1] = s * axis[k];
        r_dot[k + 1] = c * hd * axis[k];
        r_ddot[k + 1] = (c * hdd - s * hd * hd) * axis[k];
    }
}

static int fill_smooth_rows(void) {
    const double pi = 3.14159265358979323846, w = 2.0 * pi / (ROWS * STEP);
    const double a_raw[3] = {0.3, 0.2, 0.93}, b_raw[3] = {1.0, -0.5, 0.2};
    double a[3], b[3];
    const double na = sqrt(a_raw[0] * a_raw[0] + a_raw[1] * a_raw[1] + a_raw[2] * a_raw[2]),
                 nb = sqrt(b_raw[0] * b_raw[0] + b_raw[1] * b_raw[1] + b_raw[2] * b_raw[2]);
    for (int k = 0; k < 3; k++) {
        a[k] = a_raw[k] / na;
        b[k] = b_raw[k] / nb;
    }
    for (int row = 0; row < ROWS; row++) {
        const double t = STEP * row;
        const double phi = 2.0 * w * t + 0.7 * sin(w * t), phi_d = 2.0 * w + 0.7 * w * cos(w * t),
                     phi_dd = -0.7 * w * w * sin(w * t);
        const double psi = w * t + 0.5 * sin(2.0 * w * t + 1.0),
                     psi_d = w + w * cos(2.0 * w * t + 1.0),
                     psi_dd = -2.0 * w * w * sin(2.0 * w * t + 1.0);
        const double s = 1.0 + 3e-7 * sin(w * t + 0.3), s_d = 3e-7 * w * cos(w * t + 0.3),
                     s_dd = -3e-7 * w * w * sin(w * t + 0.3);
        double qa[4], qa_d[4], qa_dd[4], qb[4], qb_d[4], qb_dd[4];
        axis_rotation(a, phi, phi_d, phi_dd, qa, qa_d, qa_dd);
        axis_rotation(b, psi, psi_d, psi_dd, qb, qb_d, qb_dd);
        double u[4], u_d[4], u_dd[4], x[4], y[4];
        product(qa, qb, u);
        product(qa_d, qb, x);
        product(qa, qb_d, y);
        for (int k = 0; k < 4; k++) {
            u_d[k] = x[k] + y[k];
        }
        product(qa_dd, qb, x);
        product(qa, qb_dd, y);
        double z[4];
        product(qa_d, qb_d, z);
        for (int k = 0; k < 4; k++) {
            u_dd[k] = x[k] + 2.0 * z[k] + y[k];
        }
        for (int k = 0; k < 4; k++) { /* q = s u */
            rows[row][k] = s * u[k];
            rows[row][4 + k] = s_d * u[k] + s * u_d[k];
            rows[row][8 + k] = s_dd * u[k] + 2.0 * s_d * u_d[k] + s * u_dd[k];
        }
    }
    return check_rows();
}

static int fill_rows(const char *kind) {
    return strcmp(kind, "smooth") == 0 ? fill_smooth_rows() : fill_random_rows();
}

static void *symbol(void *library, const char *name) {
    void *s = dlsym(library, name);
    if (s == NULL) {
        fprintf(stderr, "bench_quaternion: no %s\n", name);
        exit(1);
    }
    return s;
}

#define FUNCTION(type, library, name) ((type *)(uintptr_t)symbol(library, name))

static void log_message(fmi2ComponentEnvironment e, fmi2String n, fmi2Status s, fmi2String c,
                        fmi2String m, ...) {
    (void)e, (void)n, (void)s, (void)c;
    fprintf(stderr, "bench_quaternion: %s\n", m);
}

static const fmi2CallbackFunctions CALLBACKS = {log_message, calloc, free, NULL, NULL};

static void load(fmu *f, const char *path, fmi2ValueReference first_output) {
    void *library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (library == NULL) {
        fprintf(stderr, "bench_quaternion: cannot load %s: %s\n", path, dlerror());
        exit(1);
    }
    fmi2InstantiateTYPE *instantiate = FUNCTION(fmi2InstantiateTYPE, library, "fmi2Instantiate");
    f->c = instantiate("bench", fmi2CoSimulation, f->guid, "file:///", &CALLBACKS, fmi2False,
                       fmi2False);
    f->set_real = FUNCTION(fmi2SetRealTYPE, library, "fmi2SetReal");
    f->get_real = FUNCTION(fmi2GetRealTYPE, library, "fmi2GetReal");
    f->do_step = FUNCTION(fmi2DoStepTYPE, library, "fmi2DoStep");
    f->free_instance = FUNCTION(fmi2FreeInstanceTYPE, library, "fmi2FreeInstance");
    fmi2SetupExperimentTYPE *setup =
        FUNCTION(fmi2SetupExperimentTYPE, library, "fmi2SetupExperiment");
    fmi2EnterInitializationModeTYPE *enter =
        FUNCTION(fmi2EnterInitializationModeTYPE, library, "fmi2EnterInitializationMode");
    fmi2ExitInitializationModeTYPE *exit_mode =
        FUNCTION(fmi2ExitInitializationModeTYPE, library, "fmi2ExitInitializationMode");
    /* Start from a valid attitude (the start values of q may be 0 in the description). */
    static const fmi2ValueReference q_vr[4] = {0, 1, 2, 3};
    static const double q_start[4] = {1.0, 0.0, 0.0, 0.0};
    if (f->c == NULL || setup(f->c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        f->set_real(f->c, q_vr, 4, q_start) != fmi2OK || enter(f->c) != fmi2OK ||
        exit_mode(f->c) != fmi2OK) {
        fprintf(stderr, "bench_quaternion: %s did not start\n", f->name);
        exit(1);
    }
    for (int k = 0; k < N_OUT; k++) {
        f->outputs[k] = first_output + (fmi2ValueReference)k;
    }
}

static const fmi2ValueReference INPUTS[N_IN] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};

/* n cycles: set the 12 inputs of the next row, step, get the 32 outputs. ns per cycle. */
__attribute__((noinline)) static double cycle(fmu *f, long n) {
    double y[N_OUT], sum = 0.0, t = f->time;
    unsigned int statuses = 0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        statuses |= (unsigned int)f->set_real(f->c, INPUTS, N_IN, rows[step & (ROWS - 1)]);
        statuses |= (unsigned int)f->do_step(f->c, t, STEP, fmi2True);
        t += STEP;
        statuses |= (unsigned int)f->get_real(f->c, f->outputs, N_OUT, y);
        sum += y[step % N_OUT];
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    f->time = t;
    if (statuses != 0) {
        fprintf(stderr, "bench_quaternion: a call of %s failed\n", f->name);
        exit(1);
    }
    return elapsed / (double)n;
}

/* n evaluations of the hand-written formula on the same rows. ns per evaluation. */
__attribute__((noinline)) static double anchor(long n) {
    double y[N_OUT], sum = 0.0;
    const double start = ak_bench_now_ns();
    for (long step = 0; step < n; step++) {
        ak_anchor_quaternion(rows[step & (ROWS - 1)], y);
        sum += y[step % N_OUT];
    }
    const double elapsed = ak_bench_now_ns() - start;
    sink = sum;
    return elapsed / (double)n;
}

/* The groups of the outputs (first index, length) whose sizes the check's tolerance takes. */
static const int GROUPS[][2] = {{0, 3}, {3, 3}, {6, 3}, {9, 3}, {12, 9}, {21, 1},
                                {22, 3}, {25, 3}, {28, 3}, {31, 1}};

/* Every output of the FMU's cycle on every row against the anchor's: within 1e-12 of the size of
 * its group (for theta, of pi). Prints the largest relative difference and the smallest
 * singularity distance; exits on a disagreement. */
static void check_against_anchor(fmu *f, const char *kind) {
    double largest = 0.0, nearest = INFINITY;
    for (int row = 0; row < ROWS; row++) {
        double y[N_OUT], z[N_OUT];
        if (f->set_real(f->c, INPUTS, N_IN, rows[row]) != fmi2OK ||
            f->do_step(f->c, f->time, STEP, fmi2True) != fmi2OK ||
            f->get_real(f->c, f->outputs, N_OUT, y) != fmi2OK) {
            fprintf(stderr, "bench_quaternion: %s refused %s row %d\n", f->name, kind, row);
            exit(1);
        }
        f->time += STEP;
        ak_anchor_quaternion(rows[row], z);
        for (size_t g = 0; g < sizeof GROUPS / sizeof GROUPS[0]; g++) {
            const int first = GROUPS[g][0], length = GROUPS[g][1];
            double size = 0.0;
            for (int k = first; k < first + length; k++) {
                size = fmax(size, fmax(fabs(y[k]), fabs(z[k])));
            }
            if (first == 22) {
                size = 3.14159265358979323846;
            }
            for (int k = first; k < first + length; k++) {
                const double difference = size > 0.0 ? fabs(y[k] - z[k]) / size : 0.0;
                if (!(difference <= 1e-12)) {
                    fprintf(stderr,
                            "bench_quaternion: %s row %d, output %d (value reference %d): FMU "
                            "%.17g, anchor %.17g\n",
                            kind, row, k, QK_VR_OMEGA_FIXED + k, y[k], z[k]);
                    exit(1);
                }
                largest = fmax(largest, difference);
            }
        }
        nearest = fmin(nearest, y[31]);
    }
    printf("  %s rows: the FMU's 32 outputs agree with the anchor within %.1e of their size "
           "(smallest singularity distance %.3g)\n", kind, largest, nearest);
}

static void record_figure(const char *kind, double ratio, double floor, double passthrough_ns) {
    const char *path = getenv("AK_BENCH_FIGURES");
    if (path == NULL || path[0] == '\0') {
        return;
    }
    FILE *file = fopen(path, "a");
    if (file == NULL) {
        fprintf(stderr, "bench_quaternion: cannot append to %s\n", path);
        exit(1);
    }
    fprintf(file, "qk-fmi2 %s %.4f %.4f %.2f\n", kind, ratio, floor, passthrough_ns);
    fclose(file);
}

static void time_kind(fmu *quaternion, fmu *passthrough, const char *kind, long steps,
                      int repeats) {
    if (fill_rows(kind) != 0) {
        fprintf(stderr, "bench_quaternion: two consecutive %s rows share a value\n", kind);
        exit(1);
    }
    double t_qk[MAX_REPEATS], t_pass[MAX_REPEATS], t_anchor[MAX_REPEATS], ratio[MAX_REPEATS];
    (void)cycle(quaternion, steps / 10 + 1); /* warm the caches and the branch predictors */
    (void)cycle(passthrough, steps / 10 + 1);
    (void)anchor(steps / 10 + 1);
    for (int r = 0; r < repeats; r++) { /* the order turns each repeat */
        for (int k = 0; k < 3; k++) {
            switch ((r + k) % 3) {
            case 0: t_qk[r] = cycle(quaternion, steps); break;
            case 1: t_pass[r] = cycle(passthrough, steps); break;
            default: t_anchor[r] = anchor(steps); break;
            }
        }
        ratio[r] = t_qk[r] / (t_pass[r] + t_anchor[r]);
    }
    const double r_med = ak_bench_median(ratio, repeats);
    const double c = ak_bench_median(t_qk, repeats), p = ak_bench_median(t_pass, repeats),
                 a = ak_bench_median(t_anchor, repeats);
    printf("QuaternionKinematics FMI 2 cycle (set 12 inputs, doStep, get 32 outputs), %s rows, "
           "%ld steps, median of %d repeats:\n", kind, steps, repeats);
    printf("  QuaternionKinematics %.1f ns, pass-through %.1f ns, hand-written formula %.1f ns\n",
           c, p, a);
    printf("  QuaternionKinematics / (pass-through + formula): %.3f (goal 1.3: %s)\n", r_med,
           r_med <= 1.3 ? "met" : "NOT met");
    record_figure(kind, r_med, (p + a) / a, p);
}

int main(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: bench_quaternion QK_SO PASSTHROUGH_SO [STEPS [REPEATS "
                        "[random|smooth|both [LOOP]]]]\n");
        return 2;
    }
    const long steps = argc > 3 ? (long)atof(argv[3]) : 1000000;
    const int repeats = argc > 4 ? atoi(argv[4]) : 5;
    const char *kinds = argc > 5 ? argv[5] : "both";
    const char *only = argc > 6 ? argv[6] : NULL;
    if (steps < 1 || repeats < 1 || repeats > MAX_REPEATS ||
        (strcmp(kinds, "random") != 0 && strcmp(kinds, "smooth") != 0 &&
         (strcmp(kinds, "both") != 0 || only != NULL))) {
        fprintf(stderr, "bench_quaternion: STEPS >= 1, REPEATS in 1..%d, rows random, smooth or "
                        "both (one kind with a LOOP)\n", MAX_REPEATS);
        return 2;
    }
    fmu quaternion = {.name = "QuaternionKinematics", .guid = QK_GUID};
    fmu passthrough = {.name = "the pass-through FMU", .guid = PASSTHROUGH_GUID};
    load(&quaternion, argv[1], QK_VR_OMEGA_FIXED);
    load(&passthrough, argv[2], 10); /* 32 of its 42 variables: 10..41 */
    const char *list[2] = {"random", "smooth"};
    const int first = strcmp(kinds, "smooth") == 0, last = strcmp(kinds, "random") == 0 ? 0 : 1;
    for (int k = first; k <= last; k++) { /* both kinds checked before any timing */
        if (fill_rows(list[k]) != 0) {
            fprintf(stderr, "bench_quaternion: two consecutive %s rows share a value\n", list[k]);
            return 1;
        }
        check_against_anchor(&quaternion, list[k]);
    }
    if (only != NULL) {
        (void)fill_rows(kinds);
        const double ns = strcmp(only, "quaternion") == 0    ? cycle(&quaternion, steps)
                          : strcmp(only, "passthrough") == 0 ? cycle(&passthrough, steps)
                                                             : anchor(steps);
        printf("%s: %.1f ns per cycle\n", only, ns);
        return 0;
    }
    for (int k = first; k <= last; k++) {
        time_kind(&quaternion, &passthrough, list[k], steps, repeats);
    }
    quaternion.free_instance(quaternion.c);
    passthrough.free_instance(passthrough.c);
    return 0;
}
