/* Model-side logging: format here, let the owning FMI layer send it (models/model.h). */
#include <stdarg.h>
#include <stdio.h>

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
