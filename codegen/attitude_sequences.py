"""fmu_src/core/attitude_sequences.h: the angles of each of the 24 sequences as its own function,
chain_angles of fmu_src/core/attitude_angles.c with the sequence's chain written in, and the
table that finds a sequence's function from its contents; attitude_sines_sequences.h the same for
the sines of the principal angles (chain_sines of attitude_angle_sines.c). From codegen/project.py's SEQUENCES, like every
other table of the sequences: the core types none of them by hand."""
from codegen import project
from codegen.generate import HEADER_NOTE


def chain(name):
    """(first, second chain axis, 0-based; proper Euler; space-fixed): a space-fixed sequence's
    chain starts with its last axis (kinematics_general.h, section 1)."""
    axes = project.sequence_axes(name)
    space = name.startswith("space")
    first, second = (axes[2], axes[1]) if space else (axes[0], axes[1])
    return first - 1, second - 1, project.sequence_is_proper_euler(name), space


def attitude_sequences_h():
    lines = ["/* The angles of each of the 24 rotation sequences as its own function: chain_angles",
             " * (attitude_angles.c) with the sequence's chain constant, so that its indices, signs",
             " * and the order of theta fold away; and the table of them by the sequence's contents",
             " * (a copy of an entry of AK_SEQUENCES finds its function too). Included by",
             " * attitude_angles.c.",
             f" * {HEADER_NOTE.format(source='codegen/project.py (codegen/attitude_sequences.py)')} */",
             ""]
    c_bool = {True: "true", False: "false"}
    for name in project.SEQUENCES:
        i, j, proper, space = chain(name)
        function = f"angles_{name}"
        lines += [f"static bool {function}(double R[3][3], const double previous[3], double theta[3],",
                  " " * (13 + len(function)) + "double *distance) {",
                  f"    return chain_angles({i}, {j}, {c_bool[proper]}, {c_bool[space]}, R, previous, "
                  "theta, distance);",
                  "}", ""]
    lines += ["/* By kind, proper Euler or not, first and second axis of the name (0-based); NULL where",
              " * there is no sequence. */",
              "static const ak_attitude_angles_function ANGLES_OF_SEQUENCE[2][2][3][3] = {"]
    for name in project.SEQUENCES:
        lines.append(f"    {project.sequence_table_index(name)} = angles_{name},")
    lines += ["};", ""]
    return "\n".join(lines)


def attitude_sines_sequences_h():
    lines = ["/* The sines of the principal angles of each of the 24 rotation sequences as its own",
             " * function: chain_sines (attitude_angle_sines.c) with the sequence's chain constant, as",
             " * attitude_sequences.h does for the angles, and their table by the sequence's contents.",
             " * Included by attitude_angle_sines.c.",
             f" * {HEADER_NOTE.format(source='codegen/project.py (codegen/attitude_sequences.py)')} */",
             ""]
    c_bool = {True: "true", False: "false"}
    for name in project.SEQUENCES:
        i, j, proper, space = chain(name)
        function = f"sines_{name}"
        lines += [f"static bool {function}(double R[3][3], double sin_theta[3], double cos_theta[3]) {{",
                  f"    return chain_sines({i}, {j}, {c_bool[proper]}, {c_bool[space]}, R, sin_theta, "
                  "cos_theta);",
                  "}", ""]
    lines += ["/* By kind, proper Euler or not, first and second axis of the name (0-based); NULL where",
              " * there is no sequence. */",
              "static bool (*const SINES_OF_SEQUENCE[2][2][3][3])(double R[3][3], double sin_theta[3],",
              "                                                   double cos_theta[3]) = {"]
    for name in project.SEQUENCES:
        lines.append(f"    {project.sequence_table_index(name)} = sines_{name},")
    lines += ["};", ""]
    return "\n".join(lines)


def outputs():
    from codegen.models import ROOT
    core = ROOT / "fmu_src" / "core"
    return {core / "attitude_sequences.h": attitude_sequences_h(),
            core / "attitude_sines_sequences.h": attitude_sines_sequences_h()}
