/* The checks of the C test programs, one helper for all of them (header only: each program keeps
 * its own counts).
 *
 *   ak_check(ok, format, ...)                         counts a check; when ok is false prints
 *                                                     "FAIL " and the message (printf format)
 *   ak_check_close(got, expected, tolerance, format, ...)   ok when |got - expected| <= tolerance
 *                                                     (a NaN fails); the message gets the values
 *   ak_check_count(), ak_check_failures()             the checks made, the failed ones
 *   ak_check_exit_status()                            0 when no check failed, 1 otherwise
 *
 * The counts are atomic: the programs with threads check from all of them. The first
 * AK_CHECK_PRINTED failures are printed, each with one write to stdout. */
#ifndef AK_TEST_CHECK_H
#define AK_TEST_CHECK_H

#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>

#define AK_CHECK_PRINTED 100

static int ak_check_made;
static int ak_check_failed;

static inline int ak_check_count(void) {
    return __atomic_load_n(&ak_check_made, __ATOMIC_RELAXED);
}

static inline int ak_check_failures(void) {
    return __atomic_load_n(&ak_check_failed, __ATOMIC_RELAXED);
}

static inline int ak_check_exit_status(void) {
    return ak_check_failures() == 0 ? 0 : 1;
}

/* Counts one check; on failure prints "FAIL <message><suffix>". */
static inline bool ak_check_counted(bool ok, const char *suffix, const char *format, va_list args) {
    __atomic_add_fetch(&ak_check_made, 1, __ATOMIC_RELAXED);
    if (ok) {
        return true;
    }
    if (__atomic_fetch_add(&ak_check_failed, 1, __ATOMIC_RELAXED) < AK_CHECK_PRINTED) {
        char message[768];
        const int n = snprintf(message, sizeof message, "FAIL ");
        vsnprintf(message + n, sizeof message - (size_t)n, format, args);
        fprintf(stdout, "%s%s\n", message, suffix);
        fflush(stdout);
    }
    return false;
}

__attribute__((format(printf, 2, 3))) static inline bool ak_check(bool ok, const char *format, ...) {
    va_list args;
    va_start(args, format);
    const bool result = ak_check_counted(ok, "", format, args);
    va_end(args);
    return result;
}

__attribute__((format(printf, 4, 5))) static inline bool
ak_check_close(double got, double expected, double tolerance, const char *format, ...) {
    char values[128];
    snprintf(values, sizeof values, ": got %.17g expected %.17g (tolerance %g)", got, expected,
             tolerance);
    va_list args;
    va_start(args, format);
    const bool result = ak_check_counted(fabs(got - expected) <= tolerance, values, format, args);
    va_end(args);
    return result;
}

#endif
