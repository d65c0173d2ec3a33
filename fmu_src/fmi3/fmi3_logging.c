/* FMI 3 logging. Unlike FMI 2, the message is not a printf format for the importer: it is sent
 * as formatted, without doubling '%'. */
#include "fmi3_logging.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

enum { MESSAGE_CAPACITY = 1024 };

static void format_and_send(fmi3InstanceEnvironment environment,
                            fmi3LogMessageCallback log_message, fmi3Status status,
                            const char *category, const char *format, va_list arguments) {
    char message[MESSAGE_CAPACITY];
    vsnprintf(message, sizeof message, format, arguments);
    log_message(environment, status, category, message);
}

void ak3_log(const ak3_instance *instance, ak_log_category category, fmi3Status status,
             const char *format, ...) {
    if (!ak3_log_on(instance, category)) {
        return;
    }
    va_list arguments;
    va_start(arguments, format);
    format_and_send(instance->environment, instance->log_message, status,
                    AK_LOG_CATEGORY_NAMES[category], format, arguments);
    va_end(arguments);
}

void ak3_log_before_instance(fmi3InstanceEnvironment environment,
                             fmi3LogMessageCallback log_message, const char *format, ...) {
    if (log_message == NULL) {
        return;
    }
    va_list arguments;
    va_start(arguments, format);
    format_and_send(environment, log_message, fmi3Error, AK_LOG_CATEGORY_NAMES[AK_LOG_ERROR],
                    format, arguments);
    va_end(arguments);
}
