"""ContactModel's separation datum, units caught and batch (issue 32 items 2, 4, 5): the datum's
shift against the closed form Gamma(1 + 1/a) sigma_s, round trips in each datum, the default
stated, the mean plane only where the user gives it; asperity.ImplausibleValueWarning for a unit
slip; at_separations over numpy arrays against at_separation element by element."""
import math
import warnings

import numpy as np
import pytest

import asperity


@pytest.fixture(scope="module")
def table():
    return asperity.Table.open_default()


def steel(**changes):
    values = dict(shape=2.0, height_scale=1e-6, summit_radius=1e-4, summit_density=1e10, nominal_area=1e-4,
                  contact_modulus=1.15e11)
    values.update(changes)
    return asperity.RoughSurface("weibull", "tail", **values)


def test_the_default_datum_is_the_origin_and_says_so(table):
    model = asperity.ContactModel(table, steel())
    assert model.datum == "origin"
    assert model.mean_summit_height is None
    assert model.datum_position == 0.0
    assert "datum='origin' (the default)" in repr(model)
    assert "origin" in asperity.ContactModel.__init__.__doc__
    assert "datum" in asperity.PhysicalState.__doc__


@pytest.mark.parametrize("side,shape", [("tail", 2.0), ("tail", 0.7), ("bounded", 1.3)])
def test_mean_summit_datum_is_the_origin_shifted_by_the_weibull_mean(table, side, shape):
    surface = asperity.RoughSurface("weibull", side, shape=shape, height_scale=2e-6, summit_radius=1e-4,
                                    summit_density=1e10, nominal_area=1e-4, contact_modulus=1.15e11)
    origin = asperity.ContactModel(table, surface)
    summit = asperity.ContactModel(table, surface, datum="mean-summit")
    mean = (1 if side == "tail" else -1) * math.gamma(1 + 1 / shape) * 2e-6  # closed form
    assert summit.datum_position == pytest.approx(mean, rel=1e-14)
    loads = np.geomspace(1e-3, 1e3, 25)
    a, b = origin.at_load(loads), summit.at_load(loads)
    np.testing.assert_allclose(b.separation, a.separation - mean, rtol=1e-15, atol=1e-20)  # one rounding
    np.testing.assert_allclose(b.separation, b.mean_separation, rtol=1e-15, atol=1e-20)
    # round trip in the datum
    np.testing.assert_allclose(summit.at_separation(b.separation).load, loads, rtol=1e-9)


def test_mean_plane_needs_the_users_height(table):
    with pytest.raises(asperity.Error, match="mean summit height above the mean plane"):
        asperity.ContactModel(table, steel(), datum="mean-plane")
    with pytest.raises(asperity.Error, match="goes with the mean-plane datum"):
        asperity.ContactModel(table, steel(), datum="mean-summit", mean_summit_height=1e-7)
    with pytest.raises(ValueError, match="unknown datum 'mean'"):
        asperity.ContactModel(table, steel(), datum="mean")
    plane = asperity.ContactModel(table, steel(), datum="mean-plane", mean_summit_height=3e-7)
    summit = asperity.ContactModel(table, steel(), datum="mean-summit")
    assert plane.mean_summit_height == 3e-7
    assert "datum='mean-plane' mean_summit_height=3e-07" in repr(plane)
    assert plane.at_load(1.0).separation == pytest.approx(summit.at_load(1.0).separation + 3e-7, rel=1e-14)


def test_a_unit_slip_warns_one_line_each(table):
    with pytest.warns(asperity.ImplausibleValueWarning) as caught:
        asperity.ContactModel(table, steel(summit_radius=10.0, contact_modulus=210.0))
    messages = [str(w.message) for w in caught]
    assert messages == ["summit radius 10 m is implausible (above 0.001 m): did you mean 10 µm (1e-05 m)?",
                        "contact modulus E* 210 Pa is implausible (below 1 MPa, softer than rubber): did you mean "
                        "210 GPa (2.1e+11 Pa)?"]
    assert issubclass(asperity.ImplausibleValueWarning, UserWarning)
    assert caught[0].filename == __file__  # points at the caller
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        asperity.ContactModel(table, steel())  # plausible: silent
        with pytest.raises(asperity.ImplausibleValueWarning):
            asperity.ContactModel(table, steel(height_scale=0.5))
    assert asperity.implausible_values(steel()) == []
    assert len(asperity.implausible_values(steel(summit_density=100.0, nominal_area=1.0))) == 1


@pytest.mark.parametrize("datum", ["origin", "mean-summit"])
def test_at_separations_is_at_separation_element_by_element(table, datum):
    model = asperity.ContactModel(table, steel(shape=1.6), datum=datum)
    rng = np.random.default_rng(3)
    d = np.concatenate([rng.uniform(-4e-6, 6e-6, 997), [np.nan, np.inf, -np.inf, 0.0, 1e-4, 1e300]])
    scalar = model.at_separation(d)
    fields = {"count": scalar.count, "real-area": scalar.real_area, "area-fraction": scalar.area_fraction,
              "load": scalar.load, "pressure": scalar.pressure, "stiffness": scalar.stiffness}
    for quantity, expected in fields.items():
        got = model.at_separations(quantity, d)
        assert got.shape == d.shape and got.dtype == np.float64
        special = ~(np.isfinite(expected) & (expected > 0))
        np.testing.assert_array_equal(got[special], expected[special])  # NaN, 0, inf: the same
        np.testing.assert_allclose(got[~special], expected[~special], rtol=1e-12)
        assert model.at_separations(quantity, float(d[5])) == got[5]  # a number gives a float
        out = np.empty_like(d)
        assert model.at_separations(quantity, d, out=out) is out
        # the field's spelling names the same quantity (issue 39: 'real-area' but the field real_area)
        np.testing.assert_array_equal(model.at_separations(quantity.replace("-", "_"), d), got)
        np.testing.assert_array_equal(out, got)
    grid = d[:996].reshape(12, 83)
    assert model.at_separations("load", grid).shape == (12, 83)
    with pytest.raises(ValueError, match="unknown quantity 'area'"):
        model.at_separations("area", d)


def test_the_card_takes_the_datum_names(table):
    plane = asperity.ContactModel(table, steel(), datum="mean-plane", mean_summit_height=3e-7)
    default = plane.pressure_overclosure_card(1e3, 1e8, format="abaqus")
    assert "(--overclosure-datum zero-pressure,\n**   the default)" in default
    assert default == asperity.ContactModel(table, steel()).pressure_overclosure_card(1e3, 1e8, format="abaqus")
    card = plane.pressure_overclosure_card(1e3, 1e8, format="abaqus", overclosure_datum="mean-plane")
    assert "from the mean plane of the surface heights" in card and "summit height is 3e-07 m above it" in card
    with pytest.raises(asperity.Error, match="mean-plane separation datum"):
        asperity.ContactModel(table, steel()).pressure_overclosure_card(1e3, 1e8, overclosure_datum="mean-plane")
    with pytest.raises(ValueError, match="unknown overclosure_datum"):
        plane.pressure_overclosure_card(1e3, 1e8, overclosure_datum="plane")


def test_the_card_takes_max_points_and_face_size_as_the_command(table):
    # the command line's defaults: 200 rows for calculix, none for abaqus; face_size in the card's units
    model = asperity.ContactModel(table, steel())
    rows = lambda card: [line for line in card.splitlines() if line[:1].isdigit()]
    assert len(rows(model.pressure_overclosure_card(1e3, 1e8, 1e-5, units="mm"))) <= 200  # loosened to fit
    assert len(rows(model.pressure_overclosure_card(1e3, 1e8, max_points=41, units="mm"))) == 41
    assert len(rows(model.pressure_overclosure_card(1e3, 1e8, 1e-5, format="abaqus"))) > 200
    with pytest.raises(ValueError, match="max_points"):
        model.pressure_overclosure_card(1e3, 1e8, max_points=2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the default datum has no clearance: no warning for any face
        model.pressure_overclosure_card(1e3, 1e8, units="mm", face_size=1e-3)
    with pytest.warns(UserWarning, match=r"= 0\.001 mm for faces of 1 mm"):  # 1 mm, not 1 m
        card = model.pressure_overclosure_card(1e3, 1e8, units="mm", overclosure_datum="mean-summit", face_size=1)
    assert "**   WARNING: the card reaches a clearance of" in card
    with pytest.raises(ValueError, match="face_size"):
        model.pressure_overclosure_card(1e3, 1e8, format="abaqus", face_size=1)


def test_a_full_tables_model_answers_everything(table):
    model = asperity.ContactModel(table, steel())
    assert (model.min_separation, model.max_separation) == (-math.inf, math.inf)
    assert (model.min_load, model.max_load, model.min_real_area, model.max_real_area) == (0, math.inf, 0, math.inf)


def test_an_implausible_datum_height_warns_one_line(table):
    with pytest.warns(asperity.ImplausibleValueWarning) as caught:
        asperity.ContactModel(table, steel(), datum="mean-plane", mean_summit_height=-1.0)
    assert [str(w.message) for w in caught] == [
        "mean summit height -1 m above the mean plane is implausible (below it: summits, the surface's local "
        "maxima, stand above the mean plane, typically by about the height scale sigma_s, 1e-06 m here): is its "
        "sign right?"]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        asperity.ContactModel(table, steel(), datum="mean-plane", mean_summit_height=1e-6)  # plausible: silent


@pytest.fixture(scope="module")
def bearing_model(tmp_path_factory):
    """A model on a scene table (tables/scenes/bearing.toml: s from -2 to -1e-6, bounded side), by tablegen."""
    import os
    import subprocess
    from pathlib import Path
    tablegen = os.environ.get("ASPERITY_TABLEGEN")
    if not tablegen:
        pytest.skip("ASPERITY_TABLEGEN is not set (ctest sets it)")
    path = tmp_path_factory.mktemp("scene") / "bearing.h5"
    scene = Path(__file__).resolve().parents[2] / "tables" / "scenes" / "bearing.toml"
    subprocess.run([tablegen, "--scene", str(scene), "--out", str(path)], check=True, capture_output=True)
    surface = asperity.RoughSurface("weibull", "bounded", shape=1.73, height_scale=1e-6, summit_radius=1e-4,
                                    summit_density=1e10, nominal_area=1e-4, contact_modulus=1e11)
    return asperity.ContactModel(asperity.Table.open(str(path)), surface)


def test_a_query_outside_a_scene_tables_range_warns(bearing_model):
    # NaN plus asperity.OutOfRangeWarning naming how many and the range in the query's unit (the
    # command refuses such a query)
    model = bearing_model
    assert issubclass(asperity.OutOfRangeWarning, UserWarning)
    assert model.min_separation == pytest.approx(-2e-6, rel=1e-15)
    assert model.max_separation == pytest.approx(-1e-12, rel=1e-9)
    assert 0 < model.min_load < model.max_load < math.inf
    assert 0 < model.min_real_area < model.max_real_area < math.inf
    assert model.at_load(model.max_load).load == pytest.approx(model.max_load, rel=1e-9)
    with pytest.warns(asperity.OutOfRangeWarning, match=r"1 of 3 separations outside the range the table serves "
                                                        r"\(answered NaN\): separations -2e-06 to -1e-12 m") as caught:
        state = model.at_separation(np.array([-5e-6, -1e-6, 1e-7]))
    assert caught[0].filename == __file__
    assert math.isnan(state.load[0]) and state.load[1] > 0 and state.load[2] == 0
    with pytest.warns(asperity.OutOfRangeWarning, match=r"1 of 1 loads .*: loads [0-9.e+-]+ to [0-9.e+-]+ N"):
        assert math.isnan(model.at_load(1e9).load)
    with pytest.warns(asperity.OutOfRangeWarning, match=r"1 of 1 pressures .*: nominal pressures [0-9.e+-]+ to [0-9.e+-]+ Pa"):
        assert math.isnan(model.at_pressure(1e13).load)
    with pytest.warns(asperity.OutOfRangeWarning, match=r"1 of 1 real areas .*: real areas [0-9.e+-]+ to [0-9.e+-]+ m\^2"):
        assert math.isnan(model.at_real_area(1.0).load)
    with pytest.warns(asperity.OutOfRangeWarning, match=r"2 of 4 separations"):
        out = model.at_separations("load", np.array([-5e-6, -1e-6, -1e-13, np.nan]))
    assert np.isnan(out[[0, 2, 3]]).all() and out[1] > 0
    with warnings.catch_warnings():
        warnings.simplefilter("error", asperity.OutOfRangeWarning)
        model.at_separation(-2e-7)  # inside: silent
        model.at_separations("load", np.full(5000, -1e-6))
        model.at_load(np.nan)  # NaN in, NaN out: not a range question
