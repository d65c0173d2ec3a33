/* The cross-check mode's rows in hex (driver_rows.h). */
#include "driver_rows.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int hex_digit(char c) {
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

int driver_read_row(double *values, size_t n) {
    for (size_t i = 0; i < n; i++) {
        char word[17];
        if (scanf("%16s", word) != 1 || strlen(word) != 16) {
            return 0;
        }
        uint64_t bits = 0;
        for (int k = 0; k < 16; k++) {
            const int digit = hex_digit(word[k]);
            if (digit < 0) {
                return 0;
            }
            bits = (bits << 4) | (uint64_t)digit;
        }
        memcpy(&values[i], &bits, sizeof bits);
    }
    return 1;
}

size_t driver_read_rows(double *times, double *inputs, size_t n_inputs, size_t max_rows) {
    size_t rows = 0;
    while (rows < max_rows && driver_read_row(&times[rows], 1) &&
           driver_read_row(&inputs[rows * n_inputs], n_inputs)) {
        rows++;
    }
    return rows;
}

void driver_print_row(const double *values, size_t n) {
    static const char digits[] = "0123456789abcdef";
    for (size_t i = 0; i < n; i++) {
        uint64_t bits;
        memcpy(&bits, &values[i], sizeof bits);
        char word[17];
        for (int k = 15; k >= 0; k--, bits >>= 4) {
            word[k] = digits[bits & 15u];
        }
        word[16] = '\0';
        printf(i == 0 ? "%s" : " %s", word);
    }
    printf("\n");
}

size_t driver_parse_list(const char *text, unsigned int *values, size_t max) {
    size_t count = 0;
    while (*text != '\0') {
        char *end;
        const unsigned long value = strtoul(text, &end, 10);
        if (end == text || count == max || (*end != ',' && *end != '\0')) {
            return 0;
        }
        values[count++] = (unsigned int)value;
        text = *end == ',' ? end + 1 : end;
    }
    return count;
}
