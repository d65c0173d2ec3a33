"""docs/bad_input.md must show exactly the bad-input table that the C driver test_fmi2_calls proved:
the driver makes every call of the table, checks status, message, unchanged instance and memory,
and prints the rows as it observed them."""
import subprocess

import pytest

BEGIN = "<!-- bad-input table: begin"
END = "<!-- bad-input table: end -->"


def table_in_document(root):
    text = (root / "docs" / "bad_input.md").read_text()
    start = text.index(BEGIN)
    block = text[text.index("\n", start) + 1:text.index(END)]
    return [line for line in block.splitlines() if line.strip()]


def table_observed(root):
    driver = root / "build" / "test_fmi2_calls"
    if not driver.is_file():
        pytest.fail(f"{driver} is missing: build it first (bash scripts/build.sh)")
    run = subprocess.run([str(driver), "--table"], capture_output=True, text=True)
    assert run.returncode == 0, f"test_fmi2_calls failed:\n{run.stdout}\n{run.stderr}"
    return [line for line in run.stdout.splitlines() if line.startswith("|")]


def test_document_shows_the_observed_table(root, report):
    documented = table_in_document(root)
    observed = table_observed(root)
    missing = [row for row in observed if row not in documented]
    stale = [row for row in documented if row not in observed]
    assert not missing and not stale, (
        "docs/bad_input.md differs from what the FMU does; regenerate its table with "
        "build/test_fmi2_calls --table\nnot in the document:\n" + "\n".join(missing) +
        "\nnot what the FMU does:\n" + "\n".join(stale))
    assert documented == observed  # same order too
    rows = observed[2:]  # without header and rule
    assert len(rows) == len(set(rows))
    report(f"{len(rows)} rows of docs/bad_input.md proved by test_fmi2_calls")


def test_every_row_has_status_and_message_columns(root):
    for row in table_in_document(root)[2:]:
        cells = [cell.strip() for cell in row.strip("|").split(" | ")]
        assert len(cells) == 4, row
        state, call, status, message = cells
        assert status in {"NULL", "fmi2Error", "fmi2Discard"}, row
        assert message == "(nothing logged)" or message.startswith("`"), row
