/* FMI 3 logging through the importer's logMessage callback, with fully formatted messages. */
#ifndef ANGULAR_KINEMATICS_FMI3_LOGGING_H
#define ANGULAR_KINEMATICS_FMI3_LOGGING_H

#include <stdbool.h>

#include "ak_compiler.h"
#include "fmi3_instance.h"

/* True when a message of this category reaches the importer (inline: asked on the hot path). */
static inline bool ak3_log_on(const ak3_instance *instance, ak_log_category category) {
    return instance->log_enabled[category] && instance->log_message != NULL;
}

void ak3_log(const ak3_instance *instance, ak_log_category category, fmi3Status status,
             const char *format, ...) AK_PRINTF_FORMAT(4, 5);

/* For the fmi3Instantiate* functions before an instance exists: always logs, if there is a
 * logger. */
void ak3_log_before_instance(fmi3InstanceEnvironment environment,
                             fmi3LogMessageCallback log_message, const char *format, ...)
    AK_PRINTF_FORMAT(3, 4);

#endif
