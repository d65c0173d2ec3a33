/* Logging through the master's callback, with fully formatted messages. */
#ifndef ANGULAR_KINEMATICS_FMI2_LOGGING_H
#define ANGULAR_KINEMATICS_FMI2_LOGGING_H

#include <stdbool.h>

#include "ak_compiler.h"
#include "fmi2_instance.h"

/* True when a message of this category reaches the master. Inline, so that the calls of every
 * communication point (set, step, get) ask it before ak_log: with the trace off they pay a load
 * and a branch, not a variadic call per message. */
static inline bool ak_log_on(const ak_instance *instance, ak_log_category category) {
    return instance->log_enabled[category] && instance->functions.logger != NULL;
}

/* Logs a message in a category, if that category is enabled and the master gave a logger. */
void ak_log(const ak_instance *instance, ak_log_category category, fmi2Status status,
            const char *format, ...) AK_PRINTF_FORMAT(4, 5);

/* For fmi2Instantiate, before an instance exists: always logs, if there is a logger. */
void ak_log_before_instance(const fmi2CallbackFunctions *functions, fmi2String instance_name,
                            const char *format, ...) AK_PRINTF_FORMAT(3, 4);

#endif
