/* The project's elementary functions (fmu_src/elementary/): the special values of C99 Annex F
 * (F.9.1, F.9.4) bit for bit, signed zeros included, and exact relations that every correct
 * implementation meets. Accuracy against mpmath: tests/python/test_elementary_accuracy.py. */
#include "elementary.h"
#include "elementary_asin_acos.h"
#include "elementary_sincos_three.h"
#include "test_check.h"

#include <float.h>
#include <stdint.h>
#include <string.h>

static uint64_t bits_of(double x) {
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    return b;
}

/* The same double, bit for bit (any NaN matches any NaN). */
static void check_same(double got, double expected, const char *what, double arg) {
    const int ok = (got != got && expected != expected) || bits_of(got) == bits_of(expected);
    ak_check(ok, "%s(%a): got %a, expected %a", what, arg, got, expected);
}

static void check_same2(double got, double expected, const char *what, double y, double x) {
    const int ok = (got != got && expected != expected) || bits_of(got) == bits_of(expected);
    ak_check(ok, "%s(%a, %a): got %a, expected %a", what, y, x, got, expected);
}

/* ak_sincos_three_usual against ak_sincos at x, y, z: the same bits when it takes the usual
 * path; returns whether it did (false: it must have written nothing). */
static bool three_same_as_one(double x, double y, double z) {
    const double in[3] = {x, y, z};
    double s[3] = {7.0, 7.0, 7.0}, c[3] = {7.0, 7.0, 7.0};
    const bool usual = ak_sincos_three_usual(in, s, c);
    for (int k = 0; k < 3; k++) {
        double s1, c1;
        ak_sincos(in[k], &s1, &c1);
        if (usual) {
            check_same(s[k], s1, "three sin", in[k]);
            check_same(c[k], c1, "three cos", in[k]);
        } else {
            ak_check(s[k] == 7.0 && c[k] == 7.0, "three at %a: nothing written off the usual path",
                     in[k]);
        }
    }
    return usual;
}

/* Every edge of ak_sincos's usual paths, and many angles of every size in both signs: the
 * three-angle form gives ak_sincos's bits, and takes the usual path for the angles of a model. */
static void check_sincos_three(void) {
    const double edges[] = {0x1p-27, 0x1.fffffffffffffp-28, 0x1p-10, 0x1.921fb54442d18p-1,
                            0x1.921fb54442d17p-1, 0x1.921fb54442d19p-1, 0x1p20, 0x1.fffffffffffffp19,
                            AK_PIO2_HI, AK_PI_HI, 3 * AK_PIO2_HI, 2 * AK_PI_HI, 0.0, 1.0, 3.0};
    const size_t n_edges = sizeof edges / sizeof edges[0];
    for (size_t i = 0; i < n_edges; i++) {
        for (int sign = -1; sign <= 1; sign += 2) {
            const double e = sign * edges[i];
            (void)three_same_as_one(e, 0.5, -2.0);
            (void)three_same_as_one(1.0, e, 2.5);
            (void)three_same_as_one(-3.0, 0.25, e);
            /* Near a multiple of pi/2 by about the short reduction's bound 2^-10. */
            (void)three_same_as_one(e + 0x1p-10, e - 0x1p-10, e + 0x1.0001p-10);
        }
    }
    ak_check(!three_same_as_one(1.0, INFINITY, 2.0) && !three_same_as_one(NAN, 1.0, 2.0) &&
                 !three_same_as_one(1.0, 2.0, 1e22) && !three_same_as_one(0x1p-30, 1.0, 2.0),
             "non-finite, huge and tiny angles off the usual path");
    uint64_t state = 0x2545F4914F6CDD1Dull;
    int usual = 0, n = 0;
    for (; n < 200000; n++) {
        double x[3];
        for (int k = 0; k < 3; k++) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const double unit = (double)(state >> 11) / 9007199254740992.0; /* [0, 1) */
            /* Angles within [-pi, pi] for two thirds of the draws, of any size below 2^21 else. */
            const double size = (n % 3 != 0) ? AK_PI_HI : ldexp(1.0, (int)(state % 50) - 29);
            x[k] = (2.0 * unit - 1.0) * size;
        }
        usual += three_same_as_one(x[0], x[1], x[2]);
    }
    ak_check(usual > n / 2, "the usual path taken for most angles (%d of %d)", usual, n);
}

/* ak_atan2_three against ak_atan2, bit for bit (NaN payloads too), with out aliasing y. */
static void check_atan2_three_at(const double y[3], const double x[3]) {
    double out[3] = {7.0, 7.0, 7.0}, in_place[3] = {y[0], y[1], y[2]};
    ak_atan2_three(y, x, out);
    ak_atan2_three(in_place, x, in_place);
    for (int k = 0; k < 3; k++) {
        const uint64_t expected = bits_of(ak_atan2(y[k], x[k]));
        ak_check(bits_of(out[k]) == expected && bits_of(in_place[k]) == expected,
                 "atan2_three slot %d (%a, %a): got %a (in place %a), ak_atan2 %a", k, y[k], x[k],
                 out[k], in_place[k], ak_atan2(y[k], x[k]));
    }
}

static uint64_t next_random(uint64_t *state) {
    *state = *state * 6364136223846793005ull + 1442695040888963407ull;
    uint64_t z = *state; /* the LCG's low bits are weak: mix them (splitmix64's finalizer) */
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* Uniform in [-1, 1). */
static double random_unit(uint64_t *state) {
    return 2.0 * ((double)(next_random(state) >> 11) / 9007199254740992.0) - 1.0;
}

/* A double from random bits: every sign, exponent, NaN and infinity. */
static double random_bits(uint64_t *state) {
    const uint64_t b = next_random(state);
    double x;
    memcpy(&x, &b, sizeof x);
    return x;
}

/* Near the axes and the diagonals, and at the ratios where ak_atan2 changes path: |y|/|x| about
 * 2^-k (k up to 64, past the usual 2^-60), about 1 (the swap of y and x), and about j/32 (the
 * kernel's intervals); magnitudes near the usual path's ends 2^+-600 now and then. */
static void random_edge_pair(uint64_t *state, double *y, double *x) {
    const uint64_t b = next_random(state);
    const double size = ((b >> 8) % 8 == 0) ? ldexp(1.0, 595 + (int)((b >> 11) % 11))
                                            : ((b >> 8) % 8 == 1) ? ldexp(1.0, -606 + (int)((b >> 11) % 11))
                                                                  : 1.0 + 0.5 * random_unit(state);
    double ratio;
    switch (b % 4) {
    case 0: /* near an axis */
        ratio = ldexp(1.0 + 0.5 * random_unit(state), -(int)((b >> 16) % 65));
        break;
    case 1: /* near a diagonal: a few ulps from 1 */
        ratio = 1.0 + (double)((int)((b >> 16) % 9) - 4) * 0x1p-52;
        break;
    case 2: /* near an interval edge j/32 of the kernel */
        ratio = (double)((b >> 16) % 33) / 32.0 + (double)((int)((b >> 24) % 9) - 4) * 0x1p-52;
        break;
    default: /* near a diagonal, relatively */
        ratio = 1.0 + ldexp(random_unit(state), -(int)((b >> 16) % 53));
        break;
    }
    const double small = size * ratio, large = size;
    const int flip = (int)((b >> 40) & 1), sy = (int)((b >> 41) & 1), sx = (int)((b >> 42) & 1);
    *y = (flip ? large : small) * (sy ? -1.0 : 1.0);
    *x = (flip ? small : large) * (sx ? -1.0 : 1.0);
}

/* Every special pair (signed zeros, infinities, NaN, subnormals, extremes, the ends of the usual
 * path) in every slot next to usual pairs and next to each other, and 1.2 million random triples
 * of four kinds. */
static void check_atan2_three(void) {
    const double special[] = {0.0, -0.0, 1.0, -1.0, INFINITY, -INFINITY, NAN, -NAN, 0x1p-1074,
                              -0x1p-1074, DBL_MIN, -DBL_MIN, 0x1.fffffffffffffp-1023, DBL_MAX,
                              -DBL_MAX, 0x1p-600, 0x1.fffffffffffffp-601, 0x1.fffffffffffffp+600,
                              -0x1p601, 0x1p-60, -0x1p-61, 0x1p60, 0x1p61, 3.0};
    const int n_special = (int)(sizeof special / sizeof special[0]);
    const double usual_y[3] = {0.3, -2.5, 0.75}, usual_x[3] = {-0.9, 1.5, 0.75};
    for (int a = 0; a < n_special; a++) {
        for (int b = 0; b < n_special; b++) {
            for (int slot = 0; slot < 3; slot++) {
                double y[3] = {usual_y[0], usual_y[1], usual_y[2]};
                double x[3] = {usual_x[0], usual_x[1], usual_x[2]};
                y[slot] = special[a];
                x[slot] = special[b];
                check_atan2_three_at(y, x);
            }
            /* The same pair in all three slots, and next to two other special pairs. */
            const double y3[3] = {special[a], special[a], special[(a + b) % n_special]};
            const double x3[3] = {special[b], special[(a * b + 1) % n_special], special[b]};
            check_atan2_three_at(y3, x3);
        }
    }
    uint64_t state = 0x9E3779B97F4A7C15ull;
    for (int n = 0; n < 1200000; n++) {
        double y[3], x[3];
        for (int k = 0; k < 3; k++) {
            switch (n % 4) {
            case 0:
                y[k] = random_bits(&state);
                x[k] = random_bits(&state);
                break;
            case 1:
                y[k] = random_unit(&state);
                x[k] = random_unit(&state);
                break;
            case 2:
                random_edge_pair(&state, &y[k], &x[k]);
                break;
            default:
                y[k] = random_unit(&state);
                x[k] = random_unit(&state);
                break;
            }
        }
        if (n % 4 == 3) { /* one component special, the other two usual */
            const uint64_t b = next_random(&state);
            const int slot = (int)(b % 3);
            if ((b >> 8) & 1) {
                y[slot] = special[(b >> 16) % (uint64_t)n_special];
            } else {
                x[slot] = special[(b >> 16) % (uint64_t)n_special];
            }
        }
        check_atan2_three_at(y, x);
    }
}

static double sin_of(double x) { return ak_sin(x); }
static double cos_of(double x) { return ak_cos(x); }

int main(void) {
    const double inf = INFINITY, nan_value = NAN, tiny = 0x1p-1074, pio2 = AK_PIO2_HI,
                 pi = AK_PI_HI, pio4 = AK_PIO4_HI;

    /* sin and cos (F.9.1.6, F.9.1.7): zeros keep their sign, infinities and NaN give NaN. */
    check_same(sin_of(0.0), 0.0, "sin", 0.0);
    check_same(sin_of(-0.0), -0.0, "sin", -0.0);
    check_same(cos_of(0.0), 1.0, "cos", 0.0);
    check_same(cos_of(-0.0), 1.0, "cos", -0.0);
    check_same(sin_of(tiny), tiny, "sin", tiny);
    check_same(sin_of(-DBL_MIN), -DBL_MIN, "sin", -DBL_MIN);
    check_same(sin_of(0x1p-30), 0x1p-30, "sin", 0x1p-30);
    const double non_finite[] = {inf, -inf, nan_value};
    for (int i = 0; i < 3; i++) {
        double s, c;
        ak_sincos(non_finite[i], &s, &c);
        ak_check(s != s && c != c, "sincos(%a) gives NaN, NaN (got %a, %a)", non_finite[i], s, c);
    }
    /* Odd and even: sin(-x) = -sin x, cos(-x) = cos x, on both reductions and the huge one. */
    const double arguments[] = {0.5, 1.0, 3.0, 100.0, 0x1p19 + 0.3, 0x1p20, 1e22, 0x1.6ac5b262ca1ffp+849,
                                DBL_MAX};
    for (size_t i = 0; i < sizeof arguments / sizeof arguments[0]; i++) {
        const double x = arguments[i];
        double s, c, s_neg, c_neg;
        ak_sincos(x, &s, &c);
        ak_sincos(-x, &s_neg, &c_neg);
        check_same(s_neg, -s, "sin of minus", x);
        check_same(c_neg, c, "cos of minus", x);
        ak_check(fabs(s) <= 1.0 && fabs(c) <= 1.0, "sincos(%a) within [-1, 1]", x);
        ak_check_close(s * s + c * c, 1.0, 4 * DBL_EPSILON, "sin^2 + cos^2 at %a", x);
    }
    /* Known values (correctly rounded, from mpmath): sin 1e22 (the classic test of huge-argument
     * reduction) and the doubles nearest pi and pi/2. */
    check_same(sin_of(1e22), -0x1.b453ab76bf397p-1, "sin", 1e22);
    check_same(sin_of(pi), 0x1.1a62633145c07p-53, "sin", pi);
    check_same(cos_of(pio2), 0x1.1a62633145c07p-54, "cos", pio2);

    check_sincos_three();

    /* atan (F.9.1.3) */
    check_same(ak_atan(0.0), 0.0, "atan", 0.0);
    check_same(ak_atan(-0.0), -0.0, "atan", -0.0);
    check_same(ak_atan(tiny), tiny, "atan", tiny);
    check_same(ak_atan(inf), pio2, "atan", inf);
    check_same(ak_atan(-inf), -pio2, "atan", -inf);
    check_same(ak_atan(nan_value), nan_value, "atan", nan_value);
    check_same(ak_atan(1.0), pio4, "atan", 1.0);
    check_same(ak_atan(-1.0), -pio4, "atan", -1.0);
    check_same(ak_atan(DBL_MAX), pio2, "atan", DBL_MAX);

    /* atan2 (F.9.1.4): every signed zero and infinity combination. */
    const struct { double y, x, expected; } atan2_cases[] = {
        {0.0, 0.0, 0.0}, {-0.0, 0.0, -0.0}, {0.0, -0.0, pi}, {-0.0, -0.0, -pi},
        {0.0, 1.0, 0.0}, {-0.0, 1.0, -0.0}, {0.0, -1.0, pi}, {-0.0, -1.0, -pi},
        {1.0, 0.0, pio2}, {1.0, -0.0, pio2}, {-1.0, 0.0, -pio2}, {-1.0, -0.0, -pio2},
        {1.0, -inf, pi}, {-1.0, -inf, -pi}, {1.0, inf, 0.0}, {-1.0, inf, -0.0},
        {inf, 1.0, pio2}, {-inf, 1.0, -pio2}, {inf, -1.0, pio2}, {-inf, -1.0, -pio2},
        {inf, -inf, AK_THREE_PIO4}, {-inf, -inf, -AK_THREE_PIO4}, {inf, inf, pio4}, {-inf, inf, -pio4},
        {0.0, inf, 0.0}, {-0.0, -inf, -pi}, {inf, 0.0, pio2}, {-inf, -0.0, -pio2},
        {1.0, 1.0, pio4}, {-1.0, -1.0, -AK_THREE_PIO4}, {DBL_MAX, DBL_MAX, pio4},
        {tiny, tiny, pio4}, {tiny, 1.0, tiny}, {1.0, DBL_MAX, 0x1p-1024}, {tiny, -1.0, pi},
        {DBL_MAX, tiny, pio2}, {nan_value, 1.0, nan_value}, {1.0, nan_value, nan_value},
    };
    for (size_t i = 0; i < sizeof atan2_cases / sizeof atan2_cases[0]; i++) {
        check_same2(ak_atan2(atan2_cases[i].y, atan2_cases[i].x), atan2_cases[i].expected, "atan2",
                    atan2_cases[i].y, atan2_cases[i].x);
    }
    /* atan2(y, x) = atan(y/x) for x > 0 when y/x is exact. */
    check_same2(ak_atan2(3.0, 6.0), ak_atan(0.5), "atan2", 3.0, 6.0);

    check_atan2_three();

    /* asin and acos (F.9.1.1, F.9.1.2) */
    check_same(ak_asin(0.0), 0.0, "asin", 0.0);
    check_same(ak_asin(-0.0), -0.0, "asin", -0.0);
    check_same(ak_asin(tiny), tiny, "asin", tiny);
    check_same(ak_asin(1.0), pio2, "asin", 1.0);
    check_same(ak_asin(-1.0), -pio2, "asin", -1.0);
    check_same(ak_acos(1.0), 0.0, "acos", 1.0);
    check_same(ak_acos(-1.0), pi, "acos", -1.0);
    check_same(ak_acos(0.0), pio2, "acos", 0.0);
    check_same(ak_acos(-0.0), pio2, "acos", -0.0);
    check_same(ak_asin(0.5), 0x1.0c152382d7366p-1, "asin", 0.5); /* pi/6, rounded */
    check_same(ak_acos(0.5), 0x1.0c152382d7366p+0, "acos", 0.5); /* pi/3, rounded */
    const double outside[] = {1.0 + DBL_EPSILON, -2.0, inf, -inf, nan_value};
    for (int i = 0; i < 5; i++) {
        const double a = ak_asin(outside[i]), c = ak_acos(outside[i]);
        ak_check(a != a && c != c, "asin, acos(%a) give NaN (got %a, %a)", outside[i], a, c);
    }

    printf("test_elementary: %d checks, %d failed\n", ak_check_count(), ak_check_failures());
    return ak_check_exit_status();
}
