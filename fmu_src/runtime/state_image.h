/* The byte image of an FMU state, for both FMI layers: FMI-independent. Each layer names its
 * format (magic, version, what it is called in messages, whether the input derivatives are in
 * it); the layout (little-endian, no pointers: header, the values by value reference, FMI 2's
 * input derivatives, CRC-32) is written once, in codegen/state_layout.py, which generates the
 * table and every model's size in docs/capabilities.md#fmu-state; the offsets below must be
 * that table's (tests/python/test_documentation.py reads them back from real states).
 *
 * A byte string is checked from its length to its last value before anything is decoded; a
 * check that fails logs, through the model's logger (ak_model_log), which one and the values
 * that failed it, prefixed with the calling FMI function's name. */
#ifndef ANGULAR_KINEMATICS_RUNTIME_STATE_IMAGE_H
#define ANGULAR_KINEMATICS_RUNTIME_STATE_IMAGE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "model.h"

typedef struct {
    const char *magic;         /* 8 characters */
    uint32_t version;
    const char *kind;          /* in messages: "FMU state", "FMI 3 FMU state" */
    const char *token_name;    /* in messages: "GUID", "instantiationToken" */
    const char *interface_name; /* in messages: "fmuType", "interface" */
    /* The state argument and the functions that make or size states, named in messages:
     * "FMUstate", "fmi2GetFMUstate", "fmi2DeSerializeFMUstate", "fmi2SerializedFMUstateSize". */
    const char *kind_argument;
    const char *getter;
    const char *deserializer;
    const char *sizer;
    bool input_derivatives;    /* the image holds data->input_derivatives */
} ak_state_format;

/* What the header says of the instance; the layer maps it to its own fields. */
typedef struct {
    uint32_t interface;
    uint32_t state;
    double time;
    double stop_time;
    bool stop_time_defined;
} ak_state_header;

enum {
    AK_STATE_IMAGE_HEADER_SIZE = 88, /* where the values begin */
    AK_STATE_IMAGE_MAX_SIZE = AK_STATE_IMAGE_HEADER_SIZE + 8 * AK_MAX_VARIABLES +
                              8 * AK_MAX_INPUTS * AK_MAX_INPUT_DERIVATIVE_ORDER + 4
};

size_t ak_state_image_size(const ak_state_format *format);

/* Writes the image of header and data (values, and input derivatives if the format has them)
 * into bytes, which holds ak_state_image_size(format) bytes. */
void ak_state_image_write(const ak_state_format *format, const ak_state_header *header,
                          const ak_model_data *data, unsigned char *bytes);

/* The checks of the image as such: length, magic, version, size, checksum, GUID. On success
 * *header holds the header's fields, unchecked (the layer checks the interface first). */
bool ak_state_image_check(const ak_state_format *format, const ak_model_data *data,
                          const char *function, const unsigned char *bytes, size_t size,
                          ak_state_header *header);

/* The checks of the content, after ak_state_image_check: state_possible (the header's state is
 * one an instance of its interface can be in, which the caller decides), the time fields, every value finite, every parameter one the model accepts,
 * every input derivative finite. On success, values and (if the format has them) the input
 * derivatives of the image are in *content; data itself is not touched. */
bool ak_state_image_read(const ak_state_format *format, const ak_model_data *data,
                         const char *function, const unsigned char *bytes,
                         const ak_state_header *header, bool state_possible,
                         double values[AK_MAX_VARIABLES],
                         double input_derivatives[AK_MAX_INPUTS][AK_MAX_INPUT_DERIVATIVE_ORDER]);

#endif
