"""asperity.ContactCurves: a measured surface as a table from Python. The AFM map of
tests/data/surfaces/ solved by asperity.topography.ExactContact and written with write_table,
then served: the nodes to rounding, fresh solves between them within the stored bound, the
inverse, arrays, the card, and the errors of a missing file or a table of the other kind."""
import copy
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import asperity
from asperity import topography

AFM = Path(__file__).resolve().parents[2] / "tests" / "data" / "surfaces" / "afm-zsensor-10um.txt"
PRESSURES = [1e6 * 10 ** (2 * k / 8) for k in range(9)]


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    path = tmp_path_factory.mktemp("curves") / "afm.h5"
    surface = topography.read_height_map(str(AFM))
    topography.subtract_plane(surface, topography.fit_plane(surface))
    solver = topography.ExactContact(surface, contact_modulus=1e11, tolerance=1e-10, threads=1)
    nodes = solver.write_table(path, PRESSURES, description="the AFM map")
    return path, surface, nodes


def test_nodes_round_trip(written):
    path, _, nodes = written
    curves = asperity.ContactCurves(path)
    # 5 checks an interval at least, finer where the two estimates differed
    assert len(nodes) == 9 and curves.check_points >= 40 and curves.safety_factor == 2
    assert curves.bound_method == "checks-until-settled"
    assert curves.max_rel_error == tuple(2 * e for e in curves.measured_rel_error)
    assert curves.solver_tolerance == 1e-10 and curves.contact_modulus == 1e11
    assert curves.source == "exact-contact" and curves.description == "the AFM map"
    assert "mean plane" in curves.separation_datum
    assert curves.min_pressure == pytest.approx(1e6, rel=1e-15) and curves.max_pressure == pytest.approx(1e8, rel=1e-15)
    for step in nodes:
        assert curves.pressure(step.mean_gap) == pytest.approx(step.pressure, rel=1e-14)
        assert curves.stiffness(step.mean_gap) == pytest.approx(step.stiffness_per_area, rel=1e-13)
        assert curves.area_fraction(step.mean_gap) == pytest.approx(step.area_fraction, rel=1e-14)
    table = curves.nodes
    assert list(table["separation"]) == sorted(step.mean_gap for step in nodes)
    assert np.all(np.diff(table["pressure"]) < 0)
    assert copy.copy(curves).max_separation == curves.max_separation
    assert "9 nodes" in repr(curves)


def test_fresh_solves_within_the_stored_bound(written):
    path, surface, _ = written
    curves = asperity.ContactCurves.open(path)
    solver = topography.ExactContact(surface, contact_modulus=1e11, tolerance=1e-10, threads=1)
    separations = curves.nodes["separation"]
    for u in 0.5 * (separations[1:] + separations[:-1]):
        exact = solver.at_mean_gap(u)
        assert abs(curves.pressure(exact.mean_gap) / exact.pressure - 1) <= curves.max_rel_error[0]
        assert abs(curves.stiffness(exact.mean_gap) / exact.stiffness_per_area - 1) <= curves.max_rel_error[1]
        assert abs(curves.area_fraction(exact.mean_gap) / exact.area_fraction - 1) <= curves.max_rel_error[2]


def test_arrays_inverse_and_range(written):
    curves = asperity.ContactCurves(written[0])
    u = np.linspace(curves.min_separation, curves.max_separation, 101)
    p = curves.pressure(u)
    assert p.shape == (101,) and np.all(np.diff(p) < 0)
    assert np.allclose(curves.separation_at_pressure(p), u, rtol=0, atol=1e-12 * (u[-1] - u[0]))
    assert np.all(curves.stiffness(u) > 0) and np.all(np.diff(curves.area_fraction(u)) <= 0)
    # outside the range served: NaN with asperity.OutOfRangeWarning naming the range (issue 37)
    with pytest.warns(asperity.OutOfRangeWarning, match=r"1 of 1 separations outside the range the table serves "
                                                        r"\(answered NaN\): separations [0-9.e-]+ to [0-9.e-]+ m"):
        assert math.isnan(curves.pressure(curves.max_separation * 2))
    with warnings.catch_warnings():
        warnings.simplefilter("error", asperity.OutOfRangeWarning)
        assert math.isnan(curves.pressure(float("nan")))  # NaN in: not a range question
        curves.stiffness(u)  # inside: silent
    with pytest.warns(asperity.OutOfRangeWarning, match=r"1 of 1 pressures .*: pressures [0-9.e+]+ to [0-9.e+]+ Pa"):
        assert math.isnan(curves.separation_at_pressure(1e9))
    with pytest.warns(asperity.OutOfRangeWarning, match=r"2 of 3 separations"):
        assert np.isnan(curves.area_fraction(np.array([0.0, u[5], 1.0]))[[0, 2]]).all()
    assert isinstance(curves.pressure(float(u[3])), float)


def test_states_at_separations_and_pressures_as_contact_model_names_them(written):
    # ContactModel.at_separation / at_pressure give a PhysicalState; ContactCurves the same verbs, a
    # ContactCurvesState (issue 39: one vocabulary), its fields the C++ record's
    curves = asperity.ContactCurves(written[0])
    assert asperity.ContactCurvesState._fields == ("separation", "pressure", "stiffness", "area_fraction")
    u = np.linspace(curves.min_separation, curves.max_separation, 7)
    state = curves.at_separation(u)
    assert np.array_equal(state.separation, u) and np.array_equal(state.pressure, curves.pressure(u))
    assert np.array_equal(state.stiffness, curves.stiffness(u))
    assert np.array_equal(state.area_fraction, curves.area_fraction(u))
    single = curves.at_pressure(1e7)
    assert isinstance(single.pressure, float) and single.pressure == 1e7  # as asked, exactly
    assert single.separation == curves.separation_at_pressure(1e7)
    assert single.stiffness == curves.stiffness(single.separation)
    with pytest.warns(asperity.OutOfRangeWarning, match=r"1 of 2 pressures"):
        states = curves.at_pressure([1e7, 1e9])
    assert np.isnan(states.separation[1]) and np.isnan(states.stiffness[1]) and states.pressure[0] == 1e7


def test_card_datum_keyword_is_the_models(written):
    # overclosure_datum, as ContactModel's card and the command's --overclosure-datum; `datum` is its
    # old name, still read, with a DeprecationWarning
    curves = asperity.ContactCurves(written[0])
    card = curves.pressure_overclosure_card(format="csv", overclosure_datum="mean-summit")
    with pytest.warns(DeprecationWarning, match="'datum' is now 'overclosure_datum'"):
        assert curves.pressure_overclosure_card(format="csv", datum="mean-summit") == card
    with pytest.raises(ValueError, match="give the overclosure datum once"):
        curves.pressure_overclosure_card(format="csv", overclosure_datum="origin", datum="mean-summit")
    with pytest.raises(ValueError, match="overclosure_datum"):
        curves.pressure_overclosure_card(format="csv", overclosure_datum="plane")


def test_card(written):
    curves = asperity.ContactCurves(written[0])
    card = curves.pressure_overclosure_card(format="abaqus", units="mm")
    assert "PRESSURE-OVERCLOSURE=TABULAR" in card and "in MPa" in card
    rows = card.split("TABULAR\n")[1].split()
    assert rows[0].startswith("0,") and rows[-1].startswith("100,")
    with pytest.raises(asperity.Error, match="serve pressures"):
        curves.pressure_overclosure_card(1e5, 1e7)


def test_errors(tmp_path, written):
    with pytest.raises(asperity.Error, match="No such file|missing|does not exist"):
        asperity.ContactCurves(tmp_path / "missing.h5")
    with pytest.raises(asperity.Error, match="Greenwood-Williamson integrals"):
        asperity.ContactCurves(asperity.Table.default_path())
    with pytest.raises(asperity.Error, match="contact curves"):
        asperity.Table.open(written[0])
    damaged = tmp_path / "damaged.h5"
    data = bytearray(Path(written[0]).read_bytes())
    data[len(data) // 2] ^= 1
    damaged.write_bytes(bytes(data))
    with pytest.raises(asperity.Error, match="SHA-256"):
        asperity.ContactCurves(damaged)


@pytest.fixture(scope="module")
def adhesive(tmp_path_factory):
    """An adhesive law's table (tables/scenes/jkr.toml, JKR on the approach branch), by tablegen."""
    import os
    import subprocess
    tablegen = os.environ.get("ASPERITY_TABLEGEN")
    if not tablegen:
        pytest.skip("ASPERITY_TABLEGEN is not set (ctest sets it)")
    path = tmp_path_factory.mktemp("adhesive") / "jkr.h5"
    scene = Path(__file__).resolve().parents[2] / "tables" / "scenes" / "jkr.toml"
    subprocess.run([tablegen, "--scene", str(scene), "--out", str(path)], check=True, capture_output=True)
    return asperity.ContactCurves(path)


def test_adhesive_curves(adhesive):
    curves = adhesive
    assert curves.has_tension
    pull_p, pull_u = curves.pull_off_pressure, curves.pull_off_separation
    assert pull_p < 0 and curves.min_separation < pull_u < curves.max_separation
    assert curves.min_pressure == pull_p
    assert curves.pressure(pull_u) == pytest.approx(pull_p, rel=1e-12)
    assert curves.pressure(curves.max_separation) < 0
    # the inverse on the stable branch, NaN beyond the greatest tension
    u = curves.separation_at_pressure(pull_p / 2)
    assert u < pull_u and curves.pressure(u) == pytest.approx(pull_p / 2, rel=1e-9)
    with pytest.warns(asperity.OutOfRangeWarning, match="pressures"):
        assert math.isnan(curves.separation_at_pressure(1.01 * pull_p))
    separations = np.linspace(curves.min_separation, curves.max_separation, 7)
    counts = curves.summit_count(separations)
    assert np.all(counts > 0) and np.all(np.diff(counts) < 0)
    nodes = curves.nodes
    assert set(nodes) >= {"tensile_pressure", "tensile_stiffness", "summit_count"}
    assert np.allclose(nodes["pressure"] - nodes["tensile_pressure"], curves.pressure(nodes["separation"]), rtol=0,
                       atol=1e-12 * np.max(nodes["pressure"]))
    with pytest.raises(asperity.Error, match="tension"):
        curves.pressure_overclosure_card(pull_p, curves.max_pressure)


def test_measured_curves_have_no_tension_nor_count(written):
    curves = asperity.ContactCurves(written[0])
    assert not curves.has_tension
    assert math.isnan(curves.pull_off_pressure) and math.isnan(curves.pull_off_separation)
    assert math.isnan(curves.summit_count(curves.min_separation))


def _link_group_elsewhere(table, group, other, scaled=None):
    """`group` of the table moved to the plain HDF5 file `other` (`scaled`: a dataset and a factor), an
    external link to it in its place, and the integrity header sealed again over the edit: the
    crafted table of issue 37. Written with PyTables (Debian's python3-tables; h5py is not there)."""
    tables = pytest.importorskip("tables")
    import hashlib
    import struct
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # PyTables on files it did not write
        with tables.open_file(str(table), "r") as source, tables.open_file(str(other), "w") as target:
            source.copy_node("/" + group, newparent=target.root, recursive=True)
        if scaled:
            with tables.open_file(str(other), "a") as target:
                dataset = target.get_node(f"/{group}/{scaled[0]}")
                dataset[...] = dataset[...] * scaled[1]
        with tables.open_file(str(table), "a") as crafted:
            crafted.remove_node("/" + group, recursive=True)
            crafted.create_external_link("/", group, f"{other}:/{group}")
    data = bytearray(Path(table).read_bytes())  # the header: table_schema.hpp
    payload = bytes(data[512:])
    data[24:32] = struct.pack("<Q", len(payload))
    data[32:64] = hashlib.sha256(payload).digest()
    Path(table).write_bytes(bytes(data))


def test_a_table_pointing_into_another_file_is_refused(tmp_path, written):
    curves = tmp_path / "linked-curves.h5"
    curves.write_bytes(Path(written[0]).read_bytes())
    _link_group_elsewhere(curves, "contact_curves", tmp_path / "other-curves.h5", ("pressure", 1000))
    with pytest.raises(asperity.Error, match="'contact_curves' is an external link to object '/contact_curves'"):
        asperity.ContactCurves(curves)
    with pytest.raises(asperity.Error, match="'contact_curves' is an external link"):
        asperity.ContactCurves.open(curves)
    integrals = tmp_path / "linked-integrals.h5"
    integrals.write_bytes(Path(asperity.Table.default_path()).read_bytes())
    _link_group_elsewhere(integrals, "weibull_tail", tmp_path / "other-integrals.h5")
    with pytest.raises(asperity.Error, match="'weibull_tail' is an external link to object '/weibull_tail'"):
        asperity.Table.open(integrals)
