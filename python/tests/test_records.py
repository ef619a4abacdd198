# The surface analysis's result records, each defined once by its list (record_fields.hpp): the
# JSON document's object of each record has exactly the list's written keys (and the keys its writer
# composes around them, named here), each with the value of the Python attribute of the same field;
# the Python class has exactly the list's fields as attributes (and the derived ones named here),
# each with its meaning as the docstring.
import math

import numpy as np
import pytest

import asperity
from asperity import topography


@pytest.fixture(scope="module")
def analysis():
    # with contact curves (the exact contact of the 64 x 64 map solved: its ratios too)
    field = topography.gaussian_random_field(64, 64, 1e-6, 1e-6, [topography.SpectrumComponent(2.0, 1e-16)], seed=3)
    return topography.analyse_height_map(field, topography.AnalysisOptions(
        assessment=topography.AssessmentOptions(bootstrap=40, threads=2), max_height_sample=500,
        contact=topography.ContactOptions(contact_modulus=1e11, pressures=[1e6, 1e7], curve_points=5,
                                          exact_points=2)))


def written(record):
    return {name: key for name, key, _ in topography.record_fields(record) if key is not None}


def as_json(value):
    """A Python attribute's value as the document writes it (NaN: null, an enum: its name, a tuple: a list)."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if hasattr(type(value), "__members__"):
        return value.name.replace("_", "-")
    if isinstance(value, (tuple, list)):
        return [as_json(v) for v in value]
    if isinstance(value, np.ndarray):
        return [as_json(v.item()) for v in value]
    return value


def is_record_value(value):
    """A nested record, a list of records or a record of arrays (the states): checked as its own record."""
    if isinstance(value, list) and value:
        value = value[0]
    return hasattr(type(value), "_record_fields") or hasattr(type(value), "_fields")


def same(a, b):
    if isinstance(b, float):
        return a == pytest.approx(b, rel=1e-15)
    if isinstance(b, list):
        return isinstance(a, list) and len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return a == b


# (the record, its object in the document, its Python object(s), the keys composed around its fields)
def objects(a, d):
    models = d["fits"]["summit_heights"]["models"]
    model_keys = {"description", "mean_m", "standard_deviation_m", "estimator", "interval_location_m",
                  "interval_scale_m", "interval_shape"}
    return [
        (topography.HeightStatistics, d["statistics"], [a.statistics], set()),
        (topography.SpectralMoments, d["spectral_moments"], [a.moments], {"method", "isotropic", "isotropy_limit"}),
        (topography.CorrelationLengths, d["correlation"], [a.correlation], {"lag_x_m", "lag_y_m"}),
        (topography.Summits, d["summits"], [a.summits],
         {"definition", "window_points", "min_drop_m", "count", "radius_method"}),
        (topography.SamplingRow, d["sampling_dependence"][1], [a.sampling[1]], set()),
        (topography.NoiseFloor, d["noise_floor"], [a.noise_floor], {"rule"}),
        (topography.SurfaceVerdict, d["verdict"], [a.verdict],
         {"rule", "summit_test_min_summits", "summit_test_rule", "heights_orientation", "side_rule",
          "model_for_contact"}),
        (topography.Verdict, d["fits"]["heights"]["verdict"], [a.heights.verdict], set()),
        (topography.NextSteps, d["next_steps"], [topography.next_steps(a)], set()),
        # a sample's object: its fields and its options'
        ((topography.SampleAssessment, topography.AssessmentOptions), d["fits"]["heights"],
         [a.heights, a.heights.options], {"null_distributions", "intervals", "models"}),
        # a model's object: its distribution's, its fit's and its assessment's fields together
        ((topography.HeightDistribution, topography.FitResult, topography.ModelAssessment), models[1],
         [a.summit_heights.models[1].fit.distribution, a.summit_heights.models[1].fit, a.summit_heights.models[1]],
         model_keys),
        # the document itself: the analysis's written records, and the sections composed around them
        (topography.SurfaceAnalysis, d, [a],
         {"schema", "surface", "leveling", "spectral_moments", "summits", "height_histogram", "ensemble", "fits",
          "verdict", "contact", "next_steps"}),
        (topography.ContactComparison, d["contact"], [a.contact],
         {"contact_modulus_Pa", "compared_at_pressures", "min_measured_summits_to_compare", "pressure_range_Pa",
          "tables", "measured_summits_spread", "references"}),
        *[(topography.ModelContact, m, [a.contact.models[k]], set()) for k, m in enumerate(d["contact"]["models"])],
        (topography.SamplingContact, d["contact"]["measured_summits_sampling_dependence"][0], [a.contact.sampling[0]],
         set()),
    ]


def test_the_documents_objects_are_the_records_lists(analysis):
    document = analysis.to_dict()
    for records, obj, values, composed in objects(analysis, document):
        records = records if isinstance(records, tuple) else (records,)
        keys = set()
        for record, value in zip(records, values):
            for name, key in written(record).items():
                assert key not in keys, f"{record.__name__}.{name}: key {key} twice"
                keys.add(key)
                attribute = getattr(value, name)
                if is_record_value(attribute):
                    continue  # a nested record (or a list of them): its own object, checked as its own record
                if isinstance(attribute, asperity.RoughSurface):  # a model's surface: its scales
                    assert same(obj[key]["summit_radius_m"], as_json(attribute.summit_radius)), f"{record.__name__}.{name}"
                    continue
                assert same(obj[key], as_json(attribute)), f"{record.__name__}.{name}"
        assert not keys & composed
        assert set(obj) == keys | composed, f"{records[0].__name__}: {set(obj) ^ (keys | composed)}"


def test_the_models_states_and_ratios(analysis):
    """A model's states at the pressures of interest are its record's, given their ratios by the writer."""
    document = analysis.to_dict()
    for model, obj in zip(analysis.contact.models, document["contact"]["models"]):
        assert obj["model"] == model.label
        if not model.served:
            continue
        assert [s["nominal_pressure_Pa"] for s in obj["at_pressures"]] == pytest.approx(list(model.at_pressures.pressure))
        assert len(obj["curve"]) == len(model.curve.pressure)
        if len(model.stiffness_over_exact):
            assert [s["stiffness_over_exact"] for s in obj["at_pressures"]] == pytest.approx(
                list(model.stiffness_over_exact))


# the Python attributes besides a record's fields: derived, per-summit arrays, methods
DERIVED = {
    "Summits": {"i", "j", "heights", "mean_curvatures", "kappa1", "kappa2"},
    "ModelAssessment": {"interval_method"},
    "ModelContact": {"label"},
    "ContactComparison": {"compared_at_pressures"},
}
RECORDS = ["HeightStatistics", "SpectralMoments", "CorrelationLengths", "Summits", "SamplingRow", "NoiseFloor",
           "SurfaceVerdict", "Verdict", "NextSteps", "HeightDistribution", "FitResult", "ModelAssessment", "Interval",
           "SampleAssessment", "AssessmentOptions", "SurfaceAnalysis", "ContactComparison", "ModelContact",
           "SamplingContact", "RadialPowerSpectrum"]


@pytest.mark.parametrize("name", RECORDS)
def test_the_python_attributes_are_the_records_lists(name):
    record = getattr(topography, name)
    fields = topography.record_fields(record)
    properties = {n for n, v in vars(record).items() if isinstance(v, property) and not n.startswith("_")}
    assert properties == {f[0] for f in fields} | DERIVED.get(name, set())
    for field, key, meaning in fields:
        assert getattr(record, field).__doc__ == meaning, field
        assert key is None or key.isidentifier()


def test_record_fields_refuses_another_class():
    with pytest.raises(TypeError, match="HeightMap is not a result record"):
        topography.record_fields(topography.HeightMap)
