/* The byte image of an FMU state, for both FMI layers: FMI-independent, like model_outputs.h.
 * Each layer names its format (magic, version, what it is called in messages) and keeps what is
 * its own: the state-machine states, the interface check and the FMI calls. Layout,
 * little-endian, no pointers; N is the model's number of value references, I its inputs:
 *
 *   offset size  field
 *        0    8  magic (FMI 2 "AKinFMUs", FMI 3 "AKinFMU3": neither layer reads the other's)
 *        8    4  format version
 *       12    4  total size in bytes
 *       16   40  GUID (instantiation token) of the FMU, NUL-padded
 *       56    4  interface of the instance (0 model exchange, 1 co-simulation)
 *       60    4  state-machine state (one bit of the layer's states)
 *       64    8  time
 *       72    8  stop time
 *       80    4  stop time defined (0 or 1)
 *       84    4  reserved, 0
 *       88  8 N  the values, by value reference
 *    88+8N 16 I  FMI 2 only: the input derivatives, I inputs x orders 1 and 2
 *      end-4  4  CRC-32 (IEEE 802.3, as zlib's) of the bytes before it
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
