"""docs/round_trip_ssp.svg: the connection graph of RoundTrip.ssp, drawn by
examples/ssp/ssd_to_svg.py from the SystemStructure.ssd that examples/ssp/make_ssp.py writes into
the .ssp (the .ssd alone: no FMU needed). tests/python/test_ssp.py also draws it from a built
RoundTrip.ssp and compares."""
from codegen.models import ROOT
from examples.ssp.make_ssp import ssd_xml
from examples.ssp.ssd_to_svg import svg

FIGURE = ROOT / "docs" / "round_trip_ssp.svg"


def outputs():
    return {FIGURE: svg(ssd_xml().encode())}
