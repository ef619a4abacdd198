# The surface analysis's result records, each defined once by its list (record_fields.hpp): the
# JSON document's object of each record has exactly the list's written keys (and the keys its writer
# composes around them, named here), each with the value of the Python attribute of the same field;
# the Python class has exactly the list's fields as attributes (and the derived ones named here),
# each with its meaning as the docstring.
import math

import pytest

from asperity import topography


@pytest.fixture(scope="module")
def analysis():
    field = topography.gaussian_random_field(64, 64, 1e-6, 1e-6, [topography.SpectrumComponent(2.0, 1e-16)], seed=3)
    return topography.analyse_height_map(field, topography.AnalysisOptions(
        assessment=topography.AssessmentOptions(bootstrap=40, threads=2), max_height_sample=500))


def written(record):
    return {name: key for name, key, _ in topography.record_fields(record) if key is not None}


def as_json(value):
    """A Python attribute's value as the document writes it (NaN: null, an enum: its name, a tuple: a list)."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if hasattr(type(value), "__members__"):
        return value.name.replace("_", "-")
    if isinstance(value, tuple):
        return [as_json(v) for v in value]
    return value


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
                expected = as_json(getattr(value, name))
                if hasattr(type(expected), "_record_fields"):
                    continue  # a nested record: its own object, checked as its own record
                if isinstance(expected, float):
                    assert obj[key] == pytest.approx(expected, rel=1e-15), f"{record.__name__}.{name}"
                else:
                    assert obj[key] == expected, f"{record.__name__}.{name}"
        assert not keys & composed
        assert set(obj) == keys | composed, f"{records[0].__name__}: {set(obj) ^ (keys | composed)}"


# the Python attributes besides a record's fields: derived, per-summit arrays, methods
DERIVED = {
    "Summits": {"i", "j", "heights", "mean_curvatures", "kappa1", "kappa2"},
    "ModelAssessment": {"interval_method"},
}
RECORDS = ["HeightStatistics", "SpectralMoments", "CorrelationLengths", "Summits", "SamplingRow", "NoiseFloor",
           "SurfaceVerdict", "Verdict", "NextSteps", "HeightDistribution", "FitResult", "ModelAssessment", "Interval",
           "SampleAssessment", "AssessmentOptions"]


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
