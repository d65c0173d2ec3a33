/* The text both drivers' cross-check mode reads and writes (scripts/cross_check_platforms.py is
 * the other side): doubles as the 16 hex digits of their IEEE 754 bits, so that every platform
 * reads and writes the same bits with no decimal conversion of its C library in between, and
 * value-reference lists as comma-separated decimals. */
#ifndef ANGULAR_KINEMATICS_DRIVER_ROWS_H
#define ANGULAR_KINEMATICS_DRIVER_ROWS_H

#include <stddef.h>

/* Reads n doubles from stdin; 1 when all n were read, 0 at the end of the input or on a word
 * that is not 16 hex digits. */
int driver_read_row(double *values, size_t n);

/* Reads rows of a time and n_inputs values each until the end of stdin or max_rows: the times
 * into times[r], the values into inputs[r * n_inputs ...]; the number of rows. */
size_t driver_read_rows(double *times, double *inputs, size_t n_inputs, size_t max_rows);

/* Prints n doubles in hex on one line of stdout. */
void driver_print_row(const double *values, size_t n);

/* "3,0,7" into at most max unsigned values; the count, or 0 on anything else. */
size_t driver_parse_list(const char *text, unsigned int *values, size_t max);

#endif
