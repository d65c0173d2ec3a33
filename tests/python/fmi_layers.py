"""The two FMI layers behind one interface, for the tests that check a concern both share as one
test over both (conftest's `layer` fixture: FMI 2, then FMI 3)."""
import ctypes

import numpy as np


def set_derivatives(instance, derivatives):
    """fmi2SetRealInputDerivatives of order 1 for the named inputs of an FMI 2 instance; the
    status."""
    names = list(derivatives)
    vr = (ctypes.c_uint * len(names))(*[instance.vr[n] for n in names])
    order = (ctypes.c_int * len(names))(*([1] * len(names)))
    value = (ctypes.c_double * len(names))(*derivatives.values())
    return instance.call("fmi2SetRealInputDerivatives", vr, len(names), order, value)


def observable(instance):
    """The names of every Real input and output of an FMI 2 instance's model."""
    return [v.name for v in instance.model_description.modelVariables
            if v.type == "Real" and v.causality in ("input", "output")]


class Layer:
    """One FMI version as the tests that check a concern of both layers see it: an instance
    started with inputs, its inputs set from one flat vector, its inputs and outputs as bits, a
    step, and the FMU-state functions (the same arguments in both versions), called raw."""

    def __init__(self, version):
        self.version = version
        fmi = f"fmi{version}"
        self.get, self.set, self.free = (f"{fmi}GetFMU{self.state_word}", f"{fmi}SetFMU{self.state_word}",
                                         f"{fmi}FreeFMU{self.state_word}")
        self.size = f"{fmi}SerializedFMU{self.state_word}Size"
        self.serialize = f"{fmi}SerializeFMU{self.state_word}"
        self.deserialize = "fmi2DeSerializeFMUstate" if version == 2 else "fmi3DeserializeFMUState"
        self.magic = b"AKinFMUs" if version == 2 else b"AKinFMU3"
        self.byte = ctypes.c_char if version == 2 else ctypes.c_uint8  # fmi2Byte, fmi3Byte

    @property
    def state_word(self):
        return "state" if self.version == 2 else "State"

    def __repr__(self):
        return f"FMI {self.version}"

    def expected_size(self, model):
        """92 bytes of header and CRC, 8 per value reference; FMI 2 also 16 (two input
        derivatives) per input."""
        derivatives = 16 * len(model.inputs) if self.version == 2 else 0
        assert len(model.c_table["variables"]) == model.largest_vr + 1  # no gap
        return 92 + 8 * len(model.c_table["variables"]) + derivatives

    def input_names(self, instance):
        return [v.name for v in instance.model_description.modelVariables if v.causality == "input"] \
            if self.version == 2 else instance.inputs()

    def set_inputs(self, instance, flat):
        """Every input from one flat vector, in value-reference order; the status."""
        names = self.input_names(instance)
        if self.version == 2:
            return instance.set(dict(zip(names, flat)))
        ends = np.cumsum([instance.size[n] for n in names])[:-1]
        return instance.set(dict(zip(names, np.split(np.asarray(flat, dtype=float), ends))))

    def started(self, new_instance, model, name):
        """Initialized with sequence 11 (where the model has one) and the model's valid inputs
        (FMI 2: three input derivatives too), stop time 10, stepped to t = 0.25."""
        instance = new_instance(model.name, name=name, fmi_version=self.version)
        instance.initialize(stop_time=10.0, parameters=model.start_parameters)
        assert self.set_inputs(instance, list(model.valid_inputs.values())) == 0
        if self.version == 2:
            names = model.inputs
            assert set_derivatives(instance, {names[0]: 0.5, names[len(names) // 2]: -1.0,
                                              names[-1]: 2.0}) == 0
        assert self.step(instance, 0.0, 0.25) == (0, 0.25)
        return instance

    def values(self, instance):
        """The bits of every input and output and the value of the parameter sequence if the
        model has one (FMI 2: and the bits of the last successful time)."""
        has_sequence = "sequence" in instance.vr
        if self.version == 2:
            time = np.array([instance.fmu.getRealStatus(2)])  # fmi2LastSuccessfulTime
            reals = np.concatenate([time, instance.get(observable(instance))])
            return reals.view(np.uint64).tolist() + \
                (instance.get_integer(["sequence"]) if has_sequence else [])
        values = np.concatenate(list(instance.get(instance.inputs() + instance.outputs()).values()))
        if not has_sequence:
            return values.view(np.uint64).tolist()
        sequence = (ctypes.c_int64 * 1)()
        assert instance.call("fmi3GetInt64", (ctypes.c_uint32 * 1)(instance.vr["sequence"]), 1,
                             sequence, 1) == 0
        return values.view(np.uint64).tolist() + [sequence[0]]

    def step(self, instance, t, h):
        """(status, the instance's time after the step)."""
        if self.version == 3:
            return instance.do_step(t, h)
        status = instance.call("fmi2DoStep", ctypes.c_double(t), ctypes.c_double(h), 1)
        return status, instance.fmu.getRealStatus(2)  # fmi2LastSuccessfulTime

    def get_state(self, instance, state=None):
        state = ctypes.c_void_p() if state is None else state
        assert instance.call(self.get, ctypes.byref(state)) == 0
        return state

    def serialized(self, instance, state):
        size = ctypes.c_size_t()
        assert instance.call(self.size, state, ctypes.byref(size)) == 0
        buffer = (self.byte * size.value)()
        assert instance.call(self.serialize, state, buffer, size.value) == 0
        return bytes(buffer)

    def state_image(self, instance):
        """The serialized bytes of the instance's FMU state now (the state got, serialized and
        freed)."""
        state = self.get_state(instance)
        image = self.serialized(instance, state)
        assert instance.call(self.free, ctypes.byref(state)) == 0
        return image

    def deserialized(self, instance, data):
        """(status, state) of deserializing the bytes."""
        state = ctypes.c_void_p()
        buffer = (self.byte * max(len(data), 1)).from_buffer_copy(data or b"\0")
        return instance.call(self.deserialize, buffer, len(data), ctypes.byref(state)), state

    def set_one_bad_input(self, instance, index, bad):
        """The value `bad` for input element `index` (value-reference order) in one set call that
        also sets 2.5 for the first input element (FMI 2: the two value references; FMI 3: the
        first input array and the element's array). (status, the element's name, the function)."""
        if self.version == 2:
            names = self.input_names(instance)
            first, vr = instance.vr[names[0]], instance.vr[names[index]]
            vrs = (ctypes.c_uint * 2)(first, vr)
            values = (ctypes.c_double * 2)(2.5, bad)
            return instance.call("fmi2SetReal", vrs, 2, values), names[index], "fmi2SetReal"
        arrays = self.input_names(instance)
        ends = np.cumsum([instance.size[a] for a in arrays])
        which = int(np.searchsorted(ends, index, side="right"))
        element = index - (ends[which - 1] if which else 0)
        values = {arrays[0]: [2.5] * instance.size[arrays[0]]}
        values[arrays[which]] = [2.5] * instance.size[arrays[which]]
        values[arrays[which]][element] = bad
        return instance.set(values), f"{arrays[which]}[{element + 1}]", "fmi3SetFloat64"

    def output_names(self, instance):
        """FMI 2: every output scalar; FMI 3: every output array."""
        return [v.name for v in instance.model_description.modelVariables if v.causality == "output"] \
            if self.version == 2 else instance.outputs()

    def size_of(self, instance, name):
        return 1 if self.version == 2 else instance.size[name]

    def real_call(self, instance, function, vrs, n_values, value=7.0):
        """fmi2SetReal/fmi2GetReal or fmi3SetFloat64/fmi3GetFloat64 ("Set" or "Get") of the
        value references with n_values values, all `value`; (status, the values after, the
        function's name)."""
        name = f"fmi2{function}Real" if self.version == 2 else f"fmi3{function}Float64"
        refs = (ctypes.c_uint * len(vrs))(*vrs)
        values = (ctypes.c_double * n_values)(*[value] * n_values)
        if self.version == 2:
            return instance.call(name, refs, len(vrs), values), list(values), name
        return instance.call(name, refs, len(vrs), values, n_values), list(values), name
