/* Prints the variable table, the GUID and the model identifier as JSON, so that the tests can
 * compare modelDescription.xml with what the binary is built from. */
#include <stdio.h>

#include "model_variables.h"

int main(void) {
    printf("{\n  \"modelIdentifier\": \"%s\",\n  \"guid\": \"%s\",\n  \"variables\": [\n",
           AK_MODEL_IDENTIFIER, AK_GUID);
    for (int i = 0; i < AK_N_VARIABLES; i++) {
        const ak_variable *v = &AK_VARIABLES[i];
        printf("    {\"valueReference\": %u, \"name\": \"%s\", \"causality\": \"%s\", "
               "\"declaredType\": \"%s\", \"unit\": \"%s\", \"start\": %.17g, "
               "\"description\": \"%s\", \"dependencies\": [",
               v->value_reference, v->name, ak_causality_name(v->causality), v->declared_type,
               v->unit, v->start, v->description);
        for (size_t d = 0; d < v->n_dependencies; d++) {
            printf("%s%u", d == 0 ? "" : ", ", v->dependencies[d]);
        }
        printf("]}%s\n", i + 1 < AK_N_VARIABLES ? "," : "");
    }
    printf("  ]\n}\n");
    return 0;
}
