/* Logging: the messages are formatted here, then any '%' is doubled because FMI 2.0 lets the
 * master treat the message as a printf format. */
#include "fmi2_logging.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* Long enough for the longest message (a value reference list is never echoed whole). */
enum { MESSAGE_CAPACITY = 1024 };

static void format_and_send(const fmi2CallbackFunctions *functions, fmi2String instance_name,
                            fmi2Status status, const char *category, const char *format,
                            va_list arguments) {
    char formatted[MESSAGE_CAPACITY];
    char escaped[2 * MESSAGE_CAPACITY];
    vsnprintf(formatted, sizeof formatted, format, arguments);
    size_t out = 0;
    for (size_t in = 0; formatted[in] != '\0'; in++) {
        escaped[out++] = formatted[in];
        if (formatted[in] == '%') {
            escaped[out++] = '%';
        }
    }
    escaped[out] = '\0';
    functions->logger(functions->componentEnvironment, instance_name ? instance_name : "",
                      status, category, escaped);
}

void ak_log(const ak_instance *instance, ak_log_category category, fmi2Status status,
            const char *format, ...) {
    if (!ak_log_on(instance, category)) {
        return;
    }
    va_list arguments;
    va_start(arguments, format);
    format_and_send(&instance->functions, instance->instance_name, status,
                    AK_LOG_CATEGORY_NAMES[category], format, arguments);
    va_end(arguments);
}

void ak_log_before_instance(const fmi2CallbackFunctions *functions, fmi2String instance_name,
                            const char *format, ...) {
    if (functions == NULL || functions->logger == NULL) {
        return;
    }
    va_list arguments;
    va_start(arguments, format);
    format_and_send(functions, instance_name, fmi2Error, AK_LOG_CATEGORY_NAMES[AK_LOG_ERROR], format,
                    arguments);
    va_end(arguments);
}
