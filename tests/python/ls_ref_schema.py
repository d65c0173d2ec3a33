"""Validation of FMI-LS-REF files against the schema copies in tests/schemas/fmi-ls-ref/ (their
README names the commits), with no network: the schemas import and include fmi-standard's
schemas by their raw.githubusercontent.com address, which a resolver maps to the local copies.

    errors = manifest_errors(xml_bytes, "baf43cc")   # [] when valid, else the validator's lines"""
import pathlib

from lxml import etree

SCHEMAS = pathlib.Path(__file__).resolve().parents[1] / "schemas" / "fmi-ls-ref"
FMI_STANDARD = SCHEMAS / "fmi-standard-90f3881"
REMOTE = "https://raw.githubusercontent.com/modelica/fmi-standard/main/schema/"
# The FMI-LS-REF schemas a manifest is held to: the current one and the tagged one.
MANIFEST_SCHEMAS = ("baf43cc", "v1.0.0-alpha.1")
MANIFEST = "fmi3LayeredStandardReferenceManifest.xsd"
# The experiments format of 1.0.0-alpha.1's appendix (MIME type application/x-ma-ls-experiments).
EXPERIMENTS = SCHEMAS / "v1.0.0-alpha.1" / "fmi3LayeredStandardReferenceExperiments.xsd"


class LocalCopies(etree.Resolver):
    """fmi-standard's schemas from FMI_STANDARD instead of GitHub."""

    def resolve(self, url, public_id, context):
        if url.startswith(REMOTE):
            return self.resolve_filename(str(FMI_STANDARD / url[len(REMOTE):]), context)
        return None


def schema(path):
    parser = etree.XMLParser(no_network=True)
    parser.resolvers.add(LocalCopies())
    return etree.XMLSchema(etree.parse(str(path), parser))


def errors(document, xsd):
    """The validator's messages (line: message), [] when the document is valid."""
    checker = schema(xsd)
    if checker.validate(etree.fromstring(document)):
        return []
    return [f"line {e.line}: {e.message}" for e in checker.error_log]


def manifest_errors(document, version):
    return errors(document, SCHEMAS / version / MANIFEST)


def experiments_errors(document):
    return errors(document, EXPERIMENTS)
