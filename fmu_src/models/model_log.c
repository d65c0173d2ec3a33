/* Model-side logging: format here, let the owning FMI layer send it (models/model.h). */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "model.h"

void ak_model_log(const ak_model_data *data, ak_log_category category, ak_status status,
                  const char *format, ...) {
    if (data->log == NULL) {
        return;
    }
    char message[1024];
    va_list arguments;
    va_start(arguments, format);
    vsnprintf(message, sizeof message, format, arguments);
    va_end(arguments);
    data->log(data->owner, category, status, message);
}

void ak_log_categories_reset(bool enabled[AK_N_LOG_CATEGORIES], bool calls) {
    for (int category = 0; category < AK_N_LOG_CATEGORIES; category++) {
        /* Errors and warnings are reported unless switched off; the call trace only on request. */
        enabled[category] = category != AK_LOG_CALLS || calls;
    }
}

static bool find_category(const char *name, ak_log_category *category) {
    for (int c = 0; c < AK_N_LOG_CATEGORIES; c++) {
        if (strcmp(name, AK_LOG_CATEGORY_NAMES[c]) == 0) {
            *category = (ak_log_category)c;
            return true;
        }
    }
    return false;
}

bool ak_log_categories_set(const ak_model_data *data, const char *function,
                           bool enabled[AK_N_LOG_CATEGORIES], size_t n,
                           const char *const categories[], bool on) {
    if (n > 0 && categories == NULL) {
        ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                     "%s: categories is NULL with nCategories = %zu", function, n);
        return false;
    }
    ak_log_category found;
    for (size_t i = 0; i < n; i++) { /* every name checked before anything changes */
        if (categories[i] == NULL || !find_category(categories[i], &found)) {
            ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                         "%s: categories[%zu] = \"%s\" is not a log category of this FMU "
                         "(" AK_LOG_CATEGORY_LIST ")",
                         function, i, categories[i] ? categories[i] : "(null)");
            return false;
        }
    }
    if (n == 0) {
        for (int category = 0; category < AK_N_LOG_CATEGORIES; category++) {
            enabled[category] = on;
        }
    }
    for (size_t i = 0; i < n; i++) {
        find_category(categories[i], &found);
        enabled[found] = on;
    }
    return true;
}
