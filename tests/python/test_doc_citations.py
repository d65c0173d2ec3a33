"""What the prose documents cite is true: every repository path a document names in backticks
exists (a test named as `file.py::test_name` exists in that file), the fuzzing time the
abuse-testing document gives for CI is the one scripts/test_abuse.sh uses, and the sizes of the
serialized FMU states the documents quote are the models' (conftest.fmu_state_size for FMI 2,
92 + 8 N bytes for FMI 3). `python tests/python/test_doc_citations.py` lists what the documents cite
under fmu_src/."""
import re
import subprocess
import sys

import pytest

from conftest import ROOT, fmu_state_size, project, value_references_of

DOCUMENTS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]  # CHANGELOG: history
TOP_LEVEL = set(subprocess.run(["git", "ls-tree", "--name-only", "HEAD"], cwd=ROOT, check=True,
                               capture_output=True, text=True).stdout.split())


def expanded(token):
    """The paths a cited token stands for: {h,c} alternatives and <Model> for each model."""
    paths = [token]
    braces = re.search(r"\{([^}]*)\}", token)
    if braces:
        paths = [token[:braces.start()] + x + token[braces.end():] for x in braces.group(1).split(",")]
    return [p.replace("<Model>", model) for p in paths for model in project.MODELS] \
        if "<Model>" in token else paths


def cited_paths():
    """{token: documents citing it} for every backticked word that starts with a top-level entry
    of the repository (a path, not a command's word)."""
    cited = {}
    for document in DOCUMENTS:
        for quoted in re.findall(r"`([^`\n]+)`", document.read_text()):
            for token in quoted.split():
                token = token.strip("(),;:")
                if token.split("/")[0] in TOP_LEVEL and "/" in token:
                    cited.setdefault(token, set()).add(document.name)
    return cited


def generated(path):
    """A path the build or a script writes (dist/, build*/, ...): git ignores it."""
    return subprocess.run(["git", "check-ignore", "-q", "--no-index", path], cwd=ROOT).returncode == 0


def problems(token):
    path, _, test = token.partition("::")
    if generated(path.split("*")[0].split("<")[0]):
        return []
    found = []
    for candidate in expanded(path):
        matches = list(ROOT.glob(candidate)) if "*" in candidate or "<" in candidate else \
            [ROOT / candidate] if (ROOT / candidate).exists() else []
        if "<" in candidate and not matches:  # another placeholder: any file in its place
            matches = list(ROOT.glob(re.sub(r"<[^>]*>", "*", candidate)))
        if not matches:
            found.append(f"{candidate} does not exist")
        elif test and not re.search(rf"^def {re.escape(test)}\(", matches[0].read_text(), re.M):
            found.append(f"{candidate} has no test {test}")
    return found


DOC_PATHS = cited_paths()
DOC_SOURCE_PATHS = sorted(t for t in DOC_PATHS if t.startswith("fmu_src/"))


def test_documents_cite_paths_at_all():
    assert len(DOC_PATHS) > 100 and "scripts/test.sh" in DOC_PATHS


@pytest.mark.parametrize("token", sorted(DOC_PATHS))
def test_every_cited_path_exists(token):
    assert not problems(token), f"{sorted(DOC_PATHS[token])} cite `{token}`: {problems(token)}"


def test_a_missing_path_is_found():
    assert problems("tests/python/reference_sequences.py")
    assert problems("tests/python/test_fmu_state.py::test_no_such_test")
    assert not problems("fmu_src/core/sequences.{h,c}")
    assert problems("fmu_src/fmi2/fmi2_instance.c")  # the FMI 2 layer before the runtime


def test_fuzzing_time_of_ci_is_what_test_abuse_runs():
    seconds = re.search(r'fuzz\.sh "\$\{AK_FUZZ_SECONDS:-(\d+)\}"',
                        (ROOT / "scripts" / "test_abuse.sh").read_text()).group(1)
    for document in ("abuse_testing.md", "testing.md"):
        text = (ROOT / "docs" / document).read_text()
        quoted = set(re.findall(r"`bash scripts/fuzz\.sh (\d+)` \(`AK_FUZZ_SECONDS`\)", text))
        assert quoted == {seconds}, (document, quoted, seconds)
    text = (ROOT / "docs" / "abuse_testing.md").read_text()
    assert f"fuzzes {seconds} s into a scratch folder" in text


def fmi3_state_size(model):
    return 92 + 8 * len(value_references_of(model))


def test_fmu_state_sizes_quoted_are_the_models():
    # Every model's sizes are the generated table of capabilities.md (test_documentation.py);
    # these two pages quote one size each in their prose.
    fmi3 = (ROOT / "docs" / "fmi3.md").read_text()
    attitude = re.search(r"\| yes \((\d+) bytes: the states and the co-simulation memory", fmi3)
    assert int(attitude.group(1)) == fmi3_state_size("AttitudePropagator")
    models = (ROOT / "docs" / "models.md").read_text()
    euler = re.search(r"FMU state \((\d+) bytes, the same format\)", models)
    assert int(euler.group(1)) == fmu_state_size("EulerRates")


if __name__ == "__main__":
    sys.stdout.write("".join(f"{t}  ({', '.join(sorted(DOC_PATHS[t]))})\n" for t in DOC_SOURCE_PATHS))
