/* Prints the model descriptor's identity and variable table as JSON, so that the tests can
 * compare a modelDescription.xml with what its binary is built from. Built once per model
 * (model_info_AngularKinematics, model_info_EulerRates), with that model's sources. */
#include <stdio.h>

#include "model.h"

static const char *type_name(ak_type type) {
    return type == AK_TYPE_INTEGER ? "Integer" : "Real";
}

int main(void) {
    printf("{\n  \"modelIdentifier\": \"%s\",\n  \"guid\": \"%s\",\n  \"nInputs\": %d,\n"
           "  \"variables\": [\n",
           AK_MODEL.model_identifier, AK_MODEL.guid, AK_MODEL.n_inputs);
    const char *separator = "";
    for (int vr = 0; vr < AK_MODEL.n_value_references; vr++) {
        const ak_variable *v = ak_variable_of((unsigned int)vr);
        if (v == NULL) {
            continue;
        }
        printf("%s    {\"valueReference\": %u, \"name\": \"%s\", \"causality\": \"%s\", "
               "\"type\": \"%s\", \"group\": \"%s\", \"declaredType\": \"%s\", \"unit\": \"%s\", "
               "\"start\": %.17g, \"min\": %.17g, \"max\": %.17g, \"description\": \"%s\", "
               "\"dependencies\": [",
               separator, v->value_reference, v->name, ak_causality_name(v->causality),
               type_name(v->type), v->group == AK_GROUP_LAZY ? "lazy" : "main",
               v->declared_type, v->unit, v->start, v->min, v->max, v->description);
        for (size_t d = 0; d < v->n_dependencies; d++) {
            printf("%s%u", d == 0 ? "" : ", ", v->dependencies[d]);
        }
        printf("]}");
        separator = ",\n";
    }
    printf("\n  ]\n}\n");
    return 0;
}
