"""Validation of FMI-LS-REF files against the schema copies in tests/schemas/fmi-ls-ref/ (their
README names the commits), with no network: the schemas import and include fmi-standard's
schemas by their raw.githubusercontent.com address, which is mapped to the local copies, and
only local files may be read. xmlschema, not lxml: libxml2 does not check the fixed value of an
attribute declared by reference (fmi-ls-description), xmlschema does.

    errors = manifest_errors(text, "baf43cc")   # [] when valid, else one line per fault"""
import functools
import pathlib

import xmlschema

SCHEMAS = pathlib.Path(__file__).resolve().parents[1] / "schemas" / "fmi-ls-ref"
FMI_STANDARD = SCHEMAS / "fmi-standard-90f3881"
REMOTE = "https://raw.githubusercontent.com/modelica/fmi-standard/main/schema/"
LOCAL = {REMOTE + name: str(FMI_STANDARD / name)
         for name in ("fmi3LayeredStandardManifest.xsd", "fmi3Annotation.xsd")}
# The FMI-LS-REF schemas a manifest is held to: the current one and the tagged one.
MANIFEST_SCHEMAS = ("baf43cc", "v1.0.0-alpha.1")
MANIFEST = "fmi3LayeredStandardReferenceManifest.xsd"
# The experiments format of 1.0.0-alpha.1's appendix (MIME type application/x-ma-ls-experiments).
EXPERIMENTS = SCHEMAS / "v1.0.0-alpha.1" / "fmi3LayeredStandardReferenceExperiments.xsd"


@functools.lru_cache(maxsize=None)
def schema(path):
    return xmlschema.XMLSchema10(str(path), uri_mapper=LOCAL, allow="local")


def errors(document, xsd):
    """The validator's faults, each as 'reason (at path)'; [] when the document is valid."""
    if isinstance(document, bytes):
        document = document.decode()
    return [f"{error.reason} (at {error.path})" for error in schema(xsd).iter_errors(document)]


def manifest_errors(document, version):
    return errors(document, SCHEMAS / version / MANIFEST)


def experiments_errors(document):
    return errors(document, EXPERIMENTS)
