# The surface formats' one list (ASPERITY_SURFACE_FORMATS, include/asperity/topography/
# height_map_io.hpp) in Python: each member of HeightMapFormat (made from the list) has its
# read_ID function and is taken by ReadOptions; the type stubs list the same members with the
# same values (test_stubs.py).
import pathlib

from asperity import topography

SURFACES = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "surfaces"


def test_every_format_has_its_reader_and_names():
    formats = [f for name, f in topography.HeightMapFormat.__members__.items() if name != "automatic"]
    assert formats, "no format in the list"
    for value, member in enumerate(formats, start=1):
        assert int(member) == value
        reader = getattr(topography, "read_" + member.name)
        assert reader.__doc__ and "read_height_map" in reader.__doc__
        assert topography.ReadOptions(format=member).format == member


def test_a_format_reader_reads_its_format():
    afm = SURFACES / "afm-zsensor-10um.txt"
    assert topography.read_ascii_matrix(afm).format == "ascii-matrix"
    assert topography.read_height_map(afm, format=topography.HeightMapFormat.ascii_matrix).nx == 256
