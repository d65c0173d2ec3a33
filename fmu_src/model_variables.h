/* The variable table: the one source of truth for value references, names, causalities, units,
 * start values and output dependencies. modelDescription.xml must agree with it; a test reads
 * both (through the model_info tool) and compares them, GUID included. */
#ifndef ANGULAR_KINEMATICS_MODEL_VARIABLES_H
#define ANGULAR_KINEMATICS_MODEL_VARIABLES_H

#include <stddef.h>

#define AK_MODEL_IDENTIFIER "AngularKinematics"
#define AK_GUID "{c3391885-ba93-4824-bb36-df39703b63ee}"

/* Value references. Inputs first, in the order the core takes them, then the outputs in the
 * order the core writes them, so that the instance can keep all values in one array. */
enum {
    AK_VR_THETA = 0,        /* theta[1..3]: 0, 1, 2 */
    AK_VR_THETA_DOT = 3,    /* theta_dot[1..3]: 3, 4, 5 */
    AK_VR_THETA_DDOT = 6,   /* theta_ddot[1..3]: 6, 7, 8 */
    AK_VR_OMEGA_FIXED = 9,  /* omega_fixed[1..3]: 9, 10, 11 */
    AK_VR_OMEGA_BODY = 12,  /* omega_body[1..3]: 12, 13, 14 */
    AK_VR_ALPHA_FIXED = 15, /* alpha_fixed[1..3]: 15, 16, 17 */
    AK_VR_ALPHA_BODY = 18,  /* alpha_body[1..3]: 18, 19, 20 */
    AK_N_INPUTS = 9,
    AK_N_VARIABLES = 21
};

/* No output depends on more than 7 of the 9 inputs. */
#define AK_MAX_DEPENDENCIES 7

typedef enum { AK_CAUSALITY_INPUT, AK_CAUSALITY_OUTPUT } ak_causality;

typedef struct {
    unsigned int value_reference;
    const char *name;
    ak_causality causality;
    const char *declared_type; /* a <SimpleType> of modelDescription.xml */
    const char *unit;
    double start; /* inputs only */
    const char *description;
    size_t n_dependencies; /* outputs only: the inputs it structurally depends on */
    unsigned int dependencies[AK_MAX_DEPENDENCIES];
} ak_variable;

/* Indexed by value reference: AK_VARIABLES[vr].value_reference == vr. */
extern const ak_variable AK_VARIABLES[AK_N_VARIABLES];

const char *ak_causality_name(ak_causality causality);

#endif
