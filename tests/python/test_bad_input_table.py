"""docs/bad_input.md must show exactly the bad-input tables that the C drivers proved, one per model
(build/test_fmi2_calls for AngularKinematics, build/test_fmi2_calls_EulerRates): each driver makes
every call of its table, checks status, message, unchanged instance and memory, and prints the rows
as it observed them."""
import subprocess

import pytest

MODELS = {"AngularKinematics": "test_fmi2_calls", "EulerRates": "test_fmi2_calls_EulerRates"}


def table_in_document(root, model):
    text = (root / "docs" / "bad_input.md").read_text()
    start = text.index(f"<!-- bad-input table {model}: begin")
    block = text[text.index("\n", start) + 1:text.index(f"<!-- bad-input table {model}: end -->")]
    return [line for line in block.splitlines() if line.strip()]


def table_observed(root, model):
    driver = root / "build" / MODELS[model]
    if not driver.is_file():
        pytest.fail(f"{driver} is missing: build it first (bash scripts/build.sh)")
    run = subprocess.run([str(driver), "--table"], capture_output=True, text=True)
    assert run.returncode == 0, f"{driver.name} failed:\n{run.stdout}\n{run.stderr}"
    return [line for line in run.stdout.splitlines() if line.startswith("|")]


@pytest.mark.parametrize("model", MODELS)
def test_document_shows_the_observed_table(root, report, model):
    documented = table_in_document(root, model)
    observed = table_observed(root, model)
    missing = [row for row in observed if row not in documented]
    stale = [row for row in documented if row not in observed]
    assert not missing and not stale, (
        "docs/bad_input.md differs from what the FMU does; regenerate its table with "
        "scripts/update_bad_input_table.sh\nnot in the document:\n" + "\n".join(missing) +
        "\nnot what the FMU does:\n" + "\n".join(stale))
    assert documented == observed  # same order too
    rows = observed[2:]  # without header and rule
    assert len(rows) == len(set(rows))
    report(f"{len(rows)} rows of docs/bad_input.md ({model}) proved by {MODELS[model]}")


@pytest.mark.parametrize("model", MODELS)
def test_every_row_has_status_and_message_columns(root, model):
    for row in table_in_document(root, model)[2:]:
        cells = [cell.strip() for cell in row.strip("|").split(" | ")]
        assert len(cells) == 4, row
        state, call, status, message = cells
        assert status in {"NULL", "fmi2Error", "fmi2Discard"}, row
        assert message == "(nothing logged)" or message.startswith("`"), row
