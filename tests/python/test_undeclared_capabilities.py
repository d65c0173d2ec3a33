"""What a model's description does not declare (directional and, in FMI 3, adjoint derivatives;
output derivatives) its FMUs refuse, in both FMI layers (`layer`), with one error that names the
function and the flag of the model description; the cases come from each model's description."""
import ctypes

import pytest

from codegen.models import load
from conftest import Model, project

# capability of the description: (FMI 2 function, its flag), [(FMI 3 function, its flag), ...]
CAPABILITIES = {
    "provides_directional_derivative": (
        ("fmi2GetDirectionalDerivative", 'providesDirectionalDerivative="false"'),
        [("fmi3GetDirectionalDerivative", "providesDirectionalDerivatives"),
         ("fmi3GetAdjointDerivative", "providesAdjointDerivatives")]),
    "max_output_derivative_order": (
        ("fmi2GetRealOutputDerivatives", 'maxOutputDerivativeOrder="0"'),
        [("fmi3GetOutputDerivatives", 'maxOutputDerivativeOrder="0"')]),
}
UNDECLARED = [(model, capability) for model in project.MODELS for capability in CAPABILITIES
              if not load(model).capabilities.get(capability)]


def test_some_model_leaves_each_capability_undeclared():
    assert {capability for _, capability in UNDECLARED} == set(CAPABILITIES)


def call(instance, function):
    """The function on the first output and the first input, arguments well formed."""
    out = (ctypes.c_double * 16)()
    if function.startswith("fmi2"):
        output = (ctypes.c_uint * 1)(next(v.valueReference for v in instance.model_description.modelVariables
                                          if v.causality == "output"))
        if function == "fmi2GetRealOutputDerivatives":
            return instance.call(function, output, 1, (ctypes.c_int * 1)(1), out)
        return instance.call(function, output, 1, (ctypes.c_uint * 1)(0), 1,
                             (ctypes.c_double * 1)(1.0), out)
    output, known = instance.outputs()[0], instance.inputs()[0]
    n_out, n_in = instance.size[output], instance.size[known]
    unknowns, knowns = (ctypes.c_uint32 * 1)(instance.vr[output]), (ctypes.c_uint32 * 1)(instance.vr[known])
    if function == "fmi3GetOutputDerivatives":
        return instance.call(function, unknowns, 1, (ctypes.c_int32 * 1)(1), out, n_out)
    n_seed, n_sensitivity = (n_in, n_out) if function == "fmi3GetDirectionalDerivative" else (n_out, n_in)
    return instance.call(function, unknowns, 1, knowns, 1, (ctypes.c_double * n_seed)(*[1.0] * n_seed),
                         n_seed, out, n_sensitivity)


@pytest.mark.parametrize("model_name, capability", UNDECLARED)
def test_what_the_description_does_not_declare_is_refused(model_name, capability, layer, new_instance):
    model = Model(model_name)
    fmi2, fmi3 = CAPABILITIES[capability]
    instance = layer.started(new_instance, model, "target")
    for function, flag in ([fmi2] if layer.version == 2 else fmi3):
        n_errors = len(instance.errors())
        assert call(instance, function) == 3
        errors = instance.errors()[n_errors:]
        assert len(errors) == 1, errors
        assert errors[0].startswith(function) and flag in errors[0], errors[0]
        if layer.version == 2:
            assert errors[0] == f"{function}: not provided by {model_name} (modelDescription.xml: {flag})"
