/* The byte image of an FMU state (runtime/state_image.h): written and checked here once for the
 * FMI 2 and FMI 3 layers. */
#include <math.h>
#include <string.h>

#include "ak_bytes.h"
#include "state_image.h"

enum {
    OFFSET_MAGIC = 0,
    OFFSET_VERSION = 8,
    OFFSET_SIZE = 12,
    OFFSET_TOKEN = 16,
    OFFSET_INTERFACE = 56,
    OFFSET_STATE = 60,
    OFFSET_TIME = 64,
    OFFSET_STOP_TIME = 72,
    OFFSET_STOP_TIME_DEFINED = 80,
    OFFSET_RESERVED = 84,
    OFFSET_VALUES = AK_STATE_IMAGE_HEADER_SIZE,
    TOKEN_FIELD = 40
};

static size_t offset_input_derivatives(void) {
    return (size_t)OFFSET_VALUES + 8u * (size_t)AK_MODEL.n_value_references;
}

static size_t offset_checksum(const ak_state_format *format) {
    const size_t derivatives = format->input_derivatives
                                   ? 8u * (size_t)AK_MODEL.n_inputs * AK_MAX_INPUT_DERIVATIVE_ORDER
                                   : 0u;
    return offset_input_derivatives() + derivatives;
}

size_t ak_state_image_size(const ak_state_format *format) {
    return offset_checksum(format) + 4u;
}

/* Where input k's derivative of order n + 1 is. */
static size_t offset_derivative(int k, int n) {
    return offset_input_derivatives() + 8u * (size_t)(AK_MAX_INPUT_DERIVATIVE_ORDER * k + n);
}

void ak_state_image_write(const ak_state_format *format, const ak_state_header *header,
                          const ak_model_data *data, unsigned char *bytes) {
    const size_t size = ak_state_image_size(format);
    memset(bytes, 0, size);
    memcpy(bytes + OFFSET_MAGIC, format->magic, 8);
    ak_put_u32(bytes + OFFSET_VERSION, format->version);
    ak_put_u32(bytes + OFFSET_SIZE, (uint32_t)size);
    memcpy(bytes + OFFSET_TOKEN, AK_MODEL.guid, strlen(AK_MODEL.guid));
    ak_put_u32(bytes + OFFSET_INTERFACE, header->interface);
    ak_put_u32(bytes + OFFSET_STATE, header->state);
    ak_put_f64(bytes + OFFSET_TIME, header->time);
    ak_put_f64(bytes + OFFSET_STOP_TIME, header->stop_time);
    ak_put_u32(bytes + OFFSET_STOP_TIME_DEFINED, header->stop_time_defined ? 1u : 0u);
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        ak_put_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr, data->values[vr]);
    }
    if (format->input_derivatives) {
        for (int k = 0; k < AK_MODEL.n_inputs; k++) {
            for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
                ak_put_f64(bytes + offset_derivative(k, n), data->input_derivatives[k][n]);
            }
        }
    }
    ak_put_u32(bytes + offset_checksum(format), ak_crc32(bytes, offset_checksum(format)));
}

bool ak_state_image_check(const ak_state_format *format, const ak_model_data *data,
                          const char *function, const unsigned char *bytes, size_t size,
                          ak_state_header *header) {
    if (size < OFFSET_TOKEN || memcmp(bytes + OFFSET_MAGIC, format->magic, 8) != 0) {
        ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR, "%s: the %zu bytes are not an %s %s (%s)",
                     function, size, AK_MODEL.model_identifier, format->kind,
                     size < OFFSET_TOKEN ? "too short for the header" : "wrong magic bytes");
        return false;
    }
    const uint32_t version = ak_get_u32(bytes + OFFSET_VERSION);
    if (version != format->version) {
        ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                     "%s: FMU state format version %u is not supported (this binary reads "
                     "version %u)",
                     function, version, format->version);
        return false;
    }
    const size_t expected = ak_state_image_size(format);
    const uint32_t declared = ak_get_u32(bytes + OFFSET_SIZE);
    if (size != expected || declared != expected) {
        ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                     "%s: the FMU state is %zu bytes long and declares %u bytes; format version "
                     "%u of %s has %zu bytes (truncated or extended)",
                     function, size, declared, format->version, AK_MODEL.model_identifier,
                     expected);
        return false;
    }
    const uint32_t stored = ak_get_u32(bytes + offset_checksum(format));
    const uint32_t computed = ak_crc32(bytes, offset_checksum(format));
    if (stored != computed) {
        ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                     "%s: the FMU state is corrupt: its CRC-32 is 0x%08x, the bytes give 0x%08x",
                     function, stored, computed);
        return false;
    }
    char token[TOKEN_FIELD + 1];
    memcpy(token, bytes + OFFSET_TOKEN, TOKEN_FIELD);
    token[TOKEN_FIELD] = '\0';
    if (strcmp(token, AK_MODEL.guid) != 0) {
        ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                     "%s: the FMU state is of an FMU with %s \"%s\", not this one's (%s) \"%s\"",
                     function, format->token_name, token, AK_MODEL.model_identifier,
                     AK_MODEL.guid);
        return false;
    }
    header->interface = ak_get_u32(bytes + OFFSET_INTERFACE);
    header->state = ak_get_u32(bytes + OFFSET_STATE);
    header->time = ak_get_f64(bytes + OFFSET_TIME);
    header->stop_time = ak_get_f64(bytes + OFFSET_STOP_TIME);
    header->stop_time_defined = ak_get_u32(bytes + OFFSET_STOP_TIME_DEFINED) == 1;
    return true;
}

bool ak_state_image_read(const ak_state_format *format, const ak_model_data *data,
                         const char *function, const unsigned char *bytes,
                         const ak_state_header *header, bool state_possible,
                         double values[AK_MAX_VARIABLES],
                         double input_derivatives[AK_MAX_INPUTS][AK_MAX_INPUT_DERIVATIVE_ORDER]) {
    const uint32_t stop_time_defined = ak_get_u32(bytes + OFFSET_STOP_TIME_DEFINED);
    if (!state_possible || stop_time_defined > 1 ||
        ak_get_u32(bytes + OFFSET_RESERVED) != 0 || !isfinite(header->time) ||
        !isfinite(header->stop_time)) {
        ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                     "%s: the FMU state holds an impossible header (state 0x%x, time %g, stop "
                     "time %g, stop time defined %u)",
                     function, header->state, header->time, header->stop_time,
                     stop_time_defined);
        return false;
    }
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *variable = ak_variable_of((unsigned int)vr);
        values[vr] = ak_get_f64(bytes + OFFSET_VALUES + 8 * (size_t)vr);
        if (variable == NULL) {
            continue; /* a hole of the table: never read */
        }
        if (!isfinite(values[vr])) {
            ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                         "%s: the FMU state holds %s = %g, which is not finite", function,
                         variable->name, values[vr]);
            return false;
        }
        const bool integral =
            variable->type != AK_TYPE_INTEGER || values[vr] == floor(values[vr]);
        if (variable->causality == AK_CAUSALITY_PARAMETER &&
            (!integral || ak_parameter_refusal(variable, values[vr]) != NULL)) {
            ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                         "%s: the FMU state holds the parameter %s = %.17g, which it cannot have",
                         function, variable->name, values[vr]);
            return false;
        }
    }
    if (!format->input_derivatives) {
        return true;
    }
    for (int k = 0; k < AK_MODEL.n_inputs; k++) {
        for (int n = 0; n < AK_MAX_INPUT_DERIVATIVE_ORDER; n++) {
            const double d = ak_get_f64(bytes + offset_derivative(k, n));
            if (!isfinite(d)) {
                ak_model_log(data, AK_LOG_ERROR, AK_STATUS_ERROR,
                             "%s: the FMU state holds a derivative of order %d of %s = %g, "
                             "which is not finite",
                             function, n + 1, AK_MODEL.variables[k].name, d);
                return false;
            }
            input_derivatives[k][n] = d;
        }
    }
    return true;
}
