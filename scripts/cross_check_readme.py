"""The README.md of each folder of dist/cross-check/ (scripts/make_cross_check.py), and the tool
folder's name.

TOOL_ID: the cross-check's README asks for the exporting tool's ID from fmi-standard.org's tools
list (then _data/tools.csv, now static/assets/tools.json); a new tool gets one by a pull request
to modelica/fmi-standard.org that adds its entry. AngularKinematics is not listed yet: this is the
ID such an entry would carry (letters only, as the listed IDs), to be confirmed there before the
folder is submitted."""
from examples.cross_check import START, STEP, STOP
from scripts.cross_check_platforms import HOST, RUNNERS, proof

TOOL_ID = "AngularKinematics"
TEXT = """# {model} ({interface}, FMI {version}, {platform})

The FMU `{model}.fmu` of AngularKinematics {tool_version}, made by `scripts/make_cross_check.py`.
Tool ID `{tool}`: the ID this tool asks for; it is not yet in fmi-standard.org's tools list
(AngularKinematics' docs/cosimulation.md says how a new tool gets listed).

- `{model}_in.csv`: every input at every communication point, from {start} s to {stop} s in steps
  of {step} s (input k, counted from 0: 0.2 (k mod 3 + 1) + 0.6 sin((0.7 + 0.3 k) t + 0.5 k)).
- `{model}_ref.csv`: {outputs}, {origin}.
- `{model}_ref.opt`: StartTime, StopTime, StepSize; RelTol 0: a fixed-step master, no tolerance.

The master that made the reference: set up and initialize; at each row set that row's inputs
{me_time}and read the outputs; then {advance}. {memory}

`python examples/ci_check.py --cross-check DIR` re-simulates this folder with that master (fmpy,
with the binary of the machine it runs on) and requires every value within
1e-12 + 1e-12 |reference|.
"""
STATELESS = ("The model has no state: each output row is a function of that row's inputs alone, "
             "so any master that sets a row's inputs and reads the outputs gets these numbers.")
STATEFUL = ("The model integrates its {n} states q from the inputs, so its numbers depend on the "
            "master: this one sets each row's inputs once and {how}; a master that interpolates "
            "the inputs between rows or integrates otherwise gets other numbers.")


def origin_text(platform, version, run_by):
    """Which binary computed the result, how; for a copied one the test that proves its bits.
    run_by: scripts/cross_check_platforms.origin's word."""
    if run_by == "host":
        return f"computed by this folder's {platform} binary, through fmpy (the master below)"
    if run_by == "own":
        runner = RUNNERS[platform]
        where = ("under wine" if runner.windows else
                 f"under {runner.launcher[0]}" if runner.launcher else "natively")
        driver, master = (("fmu_driver", "cross_check.py") if version == "2.0"
                          else ("fmi3_driver", "cross_check3.py"))
        return (f"computed by this folder's {platform} binary, run {where} by the master below "
                f"in C (tools/{driver}_cross_check.c, call for call the one of "
                f"examples/{master}; on the x86_64-linux binary it prints fmpy's result "
                "bit for bit: tests/python/test_cross_check_platforms.py)")
    return (f"computed by the {HOST[version]} binary through fmpy: this folder's {platform} "
            f"binary does not run on the build machine; {proof(platform)}")


def readme(model, version, interface, platform, outputs, states, run_by):
    how = (f"lets fmi{version[0]}DoStep integrate to the next row" if interface == "cs"
           else "takes one explicit Euler step per row")
    memory = STATEFUL.format(n=states, how=how) if states else STATELESS
    advance = ("step to the next row's time (fmi{}DoStep)".format(version[0]) if interface == "cs"
               else "take one explicit Euler step of the states to the next row's time"
               if states else "go to the next row")
    return TEXT.format(
        model=model, interface={"cs": "Co-Simulation", "me": "Model Exchange"}[interface],
        version=version, platform=platform, tool=TOOL_ID, tool_version=_version(),
        start=START, stop=STOP, step=STEP, outputs=", ".join(f"`{n}`" for n in outputs),
        origin=origin_text(platform, version, run_by), advance=advance, memory=memory,
        me_time=f"(after fmi{version[0]}SetTime) " if interface == "me" else "")


def _version():
    from codegen.project import VERSION
    return VERSION
