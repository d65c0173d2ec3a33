/* Test-only shared library: the project's elementary functions (fmu_src/elementary/) on arrays,
 * for the accuracy tool and test through ctypes (tools/elementary/accuracy.py,
 * tests/python/test_elementary_accuracy.py). Not in the FMU. */
#include "elementary.h"
#include "elementary_asin_acos.h"

#include <stddef.h>

#if defined(_WIN32)
#define AKE_EXPORT __declspec(dllexport)
#else
#define AKE_EXPORT __attribute__((visibility("default")))
#endif

/* function: 0 sincos (out = sin, out2 = cos), 1 atan, 2 atan2(x[i], y[i]), 3 asin, 4 acos.
 * Returns -1 for an unknown function. */
AKE_EXPORT int ake_evaluate(int function, const double *x, const double *y, double *out,
                            double *out2, size_t n) {
    for (size_t i = 0; i < n; i++) {
        switch (function) {
        case 0: ak_sincos(x[i], &out[i], &out2[i]); break;
        case 1: out[i] = ak_atan(x[i]); break;
        case 2: out[i] = ak_atan2(x[i], y[i]); break;
        case 3: out[i] = ak_asin(x[i]); break;
        case 4: out[i] = ak_acos(x[i]); break;
        default: return -1;
        }
    }
    return 0;
}
