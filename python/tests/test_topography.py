"""asperity.topography: the measured-surface library from Python, on the two real surfaces of
tests/data/surfaces/ and on synthetic ones with known answers (closed forms, numpy and scipy as
independent references); the errors; the type stubs against the submodule. Kept fast: small
bootstraps, the default table instead of generated scene tables. Run by ctest (python_tests)."""
import ast
import copy
import gc
import json
import math
import os
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import scipy.stats

import asperity
from asperity import topography

REPO = Path(__file__).resolve().parents[2]
SURFACES = REPO / "tests" / "data" / "surfaces"
AFM = SURFACES / "afm-zsensor-10um.txt"
X3P = SURFACES / "digitalsurf-650x650.x3p"


def test_the_submodule_imports_as_a_module():
    import asperity.topography as imported
    from asperity.topography import read_height_map
    assert imported is topography and read_height_map is topography.read_height_map
    assert topography.HeightMap.__module__ == "asperity.topography"


# ---- reading height maps ----

def test_read_the_real_afm_map():
    surface = topography.read_height_map(AFM)
    assert (surface.nx, surface.ny) == (256, 256) and surface.format == "ascii-matrix"
    heights = surface.heights
    assert isinstance(heights, np.ndarray) and heights.dtype == np.float64 and heights.shape == (256, 256)
    assert math.isclose(surface.dx, 10e-6 / 256, rel_tol=1e-12) and math.isclose(surface.dy, 10e-6 / 256, rel_tol=1e-12)
    assert math.isclose(surface.width, 10e-6, rel_tol=1e-12) and len(surface) == 256 * 256
    assert np.all(np.isfinite(heights)) and 1e-9 < np.std(heights) < 1e-6  # metres
    # the file's first data line is row y = 0: heights[0, :]
    first = next(line for line in AFM.read_text().splitlines() if line and not line.startswith("#"))
    assert np.allclose(heights[0, :4], [float(v) for v in first.split()[:4]], rtol=1e-15, atol=0)


def test_read_the_real_x3p_map_with_options():
    surface = topography.read_height_map(str(X3P))
    assert (surface.nx, surface.ny) == (650, 650) and surface.format == "x3p"
    assert math.isclose(surface.dx, 1.277e-7, rel_tol=1e-3) and math.isclose(surface.dy, 3.146e-7, rel_tol=1e-3)
    same = topography.read_x3p(os.fsencode(X3P), topography.ReadOptions(format="x3p"))
    assert np.array_equal(same.heights, surface.heights, equal_nan=True)
    # a pixel size given overrides the file's (keywords or ReadOptions)
    resized = topography.read_height_map(X3P, pixel_size_x=1e-6, pixel_size_y=2e-6)
    assert (resized.dx, resized.dy) == (1e-6, 2e-6)
    options = topography.ReadOptions(pixel_size_x=5e-7)
    assert options.pixel_size_y == 5e-7 and options.format == topography.HeightMapFormat.automatic


def test_heights_are_a_view_that_keeps_its_map_alive():
    surface = topography.HeightMap(np.arange(20.0).reshape(4, 5) * 1e-9, 1e-6, 2e-6)
    view = surface.heights
    view[1, 2] = 1.0
    assert surface.heights[1, 2] == 1.0
    del surface
    gc.collect()
    assert view[1, 2] == 1.0 and view[3, 4] == 19e-9


def test_height_map_from_an_array_and_gsf_round_trip(tmp_path):
    rng = np.random.default_rng(3)
    heights = rng.normal(0.0, 1e-7, (12, 17))
    heights[3, 4] = np.nan
    surface = topography.HeightMap(heights, dx=2e-7, dy=3e-7, source="mine")
    assert (surface.nx, surface.ny, surface.missing_points) == (17, 12, 1)
    assert np.array_equal(surface.heights, heights, equal_nan=True)
    assert surface.heights is not heights  # copied in
    path = tmp_path / "map.gsf"
    topography.write_gsf(surface, path)
    back = topography.read_gsf(path)
    assert (back.nx, back.ny) == (17, 12)
    assert math.isclose(back.dx, 2e-7, rel_tol=1e-6) and math.isclose(back.dy, 3e-7, rel_tol=1e-6)
    assert np.allclose(back.heights, heights, rtol=1e-6, atol=0, equal_nan=True)  # float32 in the file
    assert copy.deepcopy(surface).heights[0, 0] == surface.heights[0, 0]


def test_read_xyz_with_units(tmp_path):
    path = tmp_path / "grid.xyz"
    rows = [f"{x * 0.5} {y * 0.25} {x + 10 * y}" for y in range(3) for x in range(4)]
    path.write_text("x y z\n" + "\n".join(rows) + "\n")
    surface = topography.read_xyz(path, lateral_unit="um", height_unit="nm")
    assert (surface.nx, surface.ny) == (4, 3)
    assert math.isclose(surface.dx, 0.5e-6, rel_tol=1e-12) and math.isclose(surface.dy, 0.25e-6, rel_tol=1e-12)
    assert np.allclose(surface.heights, (np.arange(4)[None, :] + 10 * np.arange(3)[:, None]) * 1e-9, rtol=1e-12)
    with pytest.raises(asperity.Error, match="unit"):
        topography.read_xyz(path)  # xyz carries no units


def test_read_errors_name_the_problem(tmp_path):
    with pytest.raises(asperity.Error, match="no such file"):
        topography.read_height_map(tmp_path / "missing.x3p")
    truncated = tmp_path / "truncated.x3p"
    truncated.write_bytes(X3P.read_bytes()[:5000])
    with pytest.raises(asperity.Error, match="truncated.x3p"):
        topography.read_height_map(truncated)
    with pytest.raises(asperity.Error):
        topography.read_height_map(AFM, format="x3p")
    with pytest.raises(ValueError, match="unknown height map format 'tiff'"):
        topography.ReadOptions(format="tiff")
    with pytest.raises(TypeError):
        topography.read_height_map(AFM, topography.ReadOptions(), format="gsf")
    with pytest.raises(asperity.Error):
        topography.HeightMap(np.zeros((2, 2)), 1e-6, 1e-6)  # fewer than 3 x 3 points
    with pytest.raises(asperity.Error):
        topography.HeightMap(np.zeros((4, 4)), -1e-6, 1e-6)
    with pytest.raises(ValueError, match="2-d"):
        topography.HeightMap(np.zeros(16), 1e-6, 1e-6)


def test_paths_are_the_bytes_the_system_sees(tmp_path):
    surface = topography.HeightMap(np.arange(16.0).reshape(4, 4) * 1e-9, 1e-6, 1e-6)
    with pytest.raises(ValueError, match="NUL"):  # the C library would stop at the NUL: another file
        topography.write_gsf(surface, str(tmp_path / "map.gsf") + "\0.txt")
    with pytest.raises(ValueError, match="NUL"):
        topography.read_height_map(os.fsencode(AFM) + b"\0ignored")
    with pytest.raises(TypeError, match="str, bytes or os.PathLike"):
        topography.read_height_map(42)
    # a name that is not UTF-8: written, listed, read back; the map's source as os.fsdecode gives it
    name = os.fsencode(tmp_path) + b"/h\xff\xfe.gsf"
    topography.write_gsf(surface, name)
    assert os.listdir(os.fsencode(tmp_path)) == [b"h\xff\xfe.gsf"]
    for spelled in (name, os.fsdecode(name), Path(os.fsdecode(name))):
        back = topography.read_height_map(spelled)
        assert np.allclose(back.heights, surface.heights, rtol=1e-6) and back.source == os.fsdecode(name)
        assert "h\udcff\udcfe.gsf" in repr(back)
    back.source = b"other\xff"
    assert back.source == os.fsdecode(b"other\xff")
    with pytest.raises(asperity.Error, match=r"missing\\xFF\.x3p"):
        topography.read_height_map(os.fsencode(tmp_path) + b"/missing\xff.x3p")
    options = topography.ContactOptions(1e11, table_path=name)
    assert options.table_path == os.fsdecode(name)
    with pytest.raises(ValueError, match="NUL"):
        options.table_path = "a\0b"


def test_units():
    assert topography.length_unit_in_metres("µm") == 1e-6 and topography.length_unit_in_metres("nm") == 1e-9
    assert math.isclose(topography.parse_length("1.5um"), 1.5e-6, rel_tol=1e-15)
    assert math.isclose(topography.parse_length("3", "nm"), 3e-9, rel_tol=1e-15)
    with pytest.raises(asperity.Error, match="needs its unit"):
        topography.parse_length("3")
    with pytest.raises(asperity.Error):
        topography.length_unit_in_metres("furlong")


# ---- leveling, statistics, moments (numpy as the reference) ----

def test_fit_and_subtract_a_plane():
    ny, nx, dx, dy = 20, 30, 1e-6, 2e-6
    x, y = np.arange(nx) * dx, np.arange(ny)[:, None] * dy
    surface = topography.HeightMap(3e-8 + 0.01 * x + (-0.02) * y + 0 * x, dx, dy)
    plane = topography.fit_plane(surface)
    assert math.isclose(plane.slope_x, 0.01, rel_tol=1e-9) and math.isclose(plane.slope_y, -0.02, rel_tol=1e-9)
    assert math.isclose(plane.offset, 3e-8, rel_tol=1e-6)
    heights = surface.heights  # the view sees the change in place
    topography.subtract_plane(surface, plane)
    assert np.max(np.abs(heights)) < 1e-18


def test_height_statistics_against_numpy():
    heights = np.random.default_rng(5).gamma(2.0, 1e-8, (40, 50))
    heights[7, 7] = np.nan
    stats = topography.height_statistics(topography.HeightMap(heights, 1e-6, 1e-6))
    valid = heights[np.isfinite(heights)]
    centred = valid - valid.mean()
    rms = math.sqrt(np.mean(centred ** 2))
    assert (stats.valid_points, stats.missing_points) == (valid.size, 1)
    assert math.isclose(stats.mean, valid.mean(), rel_tol=1e-12)
    assert math.isclose(stats.rms, rms, rel_tol=1e-12)
    assert math.isclose(stats.mean_absolute, np.mean(np.abs(centred)), rel_tol=1e-12)
    assert math.isclose(stats.skewness, np.mean(centred ** 3) / rms ** 3, rel_tol=1e-10)
    assert math.isclose(stats.kurtosis, np.mean(centred ** 4) / rms ** 4, rel_tol=1e-10)
    assert (stats.min, stats.max) == (valid.min(), valid.max())


def test_spectral_moments_against_numpy_finite_differences():
    # one consistent scheme: forward differences for slopes, second differences for curvatures,
    # the forward mixed difference; McCool's equivalent isotropic m2, m4 (geometric means along the
    # principal directions of the slope tensor)
    dx, dy = 1e-6, 2e-6
    h = np.random.default_rng(7).normal(0.0, 1e-8, (30, 40))
    h += np.linspace(0, 3e-8, 40)[None, :] * np.linspace(1, 2, 30)[:, None]  # a twist: the axes are not principal
    moments = topography.spectral_moments(topography.HeightMap(h, dx, dy))
    c = h - h.mean()
    sx = (c[:, 1:] - c[:, :-1]) / dx
    sy = (c[1:, :] - c[:-1, :]) / dy
    m2x, m2y, m11 = np.mean(sx ** 2), np.mean(sy ** 2), np.mean(sx[:-1, :] * sy[:, :-1])
    hxx = (c[:, 2:] - 2 * c[:, 1:-1] + c[:, :-2]) / dx ** 2
    hyy = (c[2:, :] - 2 * c[1:-1, :] + c[:-2, :]) / dy ** 2
    m4x, m4y = np.mean(hxx ** 2), np.mean(hyy ** 2)
    assert math.isclose(moments.m0, np.mean(c ** 2), rel_tol=1e-12)
    for got, expected in ((moments.m2x, m2x), (moments.m2y, m2y), (moments.m11, m11), (moments.m4x, m4x),
                          (moments.m4y, m4y)):
        assert math.isclose(got, expected, rel_tol=1e-10)
    values, vectors = np.linalg.eigh(np.array([[m2x, m11], [m11, m2y]]))
    assert math.isclose(moments.m2_principal[0], values[1], rel_tol=1e-10)
    assert math.isclose(moments.m2_principal[1], values[0], rel_tol=1e-10)
    assert math.isclose(moments.anisotropy, values[1] / values[0], rel_tol=1e-10)
    # curvature along the principal directions, at the interior points where all three differences exist
    cxx, cyy = hxx[1:-1, :], hyy[:, 1:-1]
    cxy = (c[2:, 2:] - c[1:-1, 2:] - c[2:, 1:-1] + c[1:-1, 1:-1]) / (dx * dy)
    m4_along = []
    for theta in (moments.principal_angle, moments.principal_angle + math.pi / 2):
        co, si = math.cos(theta), math.sin(theta)
        m4_along.append(np.mean((co * co * cxx + 2 * co * si * cxy + si * si * cyy) ** 2))
    assert math.isclose(moments.m4_principal[0], m4_along[0], rel_tol=1e-9)
    assert math.isclose(moments.m4_principal[1], m4_along[1], rel_tol=1e-9)
    assert math.isclose(moments.m2, math.sqrt(values[0] * values[1]), rel_tol=1e-10)
    assert math.isclose(moments.m4, math.sqrt(m4_along[0] * m4_along[1]), rel_tol=1e-9)
    assert math.isclose(moments.alpha, moments.m0 * moments.m4 / moments.m2 ** 2, rel_tol=1e-12)


# ---- summits on a surface with known summits ----

def test_find_summits_where_they_are():
    ny, nx, dx, dy, bump = 30, 40, 1e-6, 2e-6, 1e-8
    i, j = np.meshgrid(np.arange(nx), np.arange(ny))
    heights = -(i + 2 * j) * 1e-10  # a tilted plane: no maximum inside
    places = [(5, 5), (20, 12), (33, 25)]
    for x, y in places:
        heights[y, x] += bump
    summits = topography.find_summits(topography.HeightMap(heights, dx, dy))
    assert len(summits) == 3
    assert sorted(zip(summits.i.tolist(), summits.j.tolist())) == sorted(places)
    assert summits.i.dtype == np.int64 and summits.heights.dtype == np.float64
    assert np.allclose(summits.heights, [heights[y, x] for x, y in zip(summits.i, summits.j)], rtol=0, atol=0)
    # a bump b on a plane: h_xx = -2b/dx^2, h_yy = -2b/dy^2, h_xy = 0
    kappa_m = bump * (1 / dx ** 2 + 1 / dy ** 2)
    assert np.allclose(summits.mean_curvatures, kappa_m, rtol=1e-9)
    assert np.allclose(summits.kappa1, 2 * bump / dx ** 2, rtol=1e-9)
    assert np.allclose(summits.kappa2, 2 * bump / dy ** 2, rtol=1e-9)
    assert math.isclose(summits.radius, 1 / kappa_m, rel_tol=1e-9)
    assert math.isclose(summits.density, 3 / summits.area_searched, rel_tol=1e-12)
    # a larger window or a height threshold
    assert len(topography.find_summits(topography.HeightMap(heights, dx, dy), window=3)) == 3
    assert len(topography.find_summits(topography.HeightMap(heights, dx, dy), min_drop=2 * bump)) == 0
    with pytest.raises(asperity.Error):
        topography.find_summits(topography.HeightMap(heights, dx, dy), topography.SummitOptions(window=0))
    coarse = topography.decimated(topography.HeightMap(heights, dx, dy), 2)
    assert (coarse.nx, coarse.ny, coarse.dx) == (20, 15, 2 * dx)


# ---- height distributions against scipy ----

def scipy_reference(model, location, scale, shape):
    if model == "gaussian":
        return scipy.stats.norm(location, scale), 1
    if model == "weibull_tail":
        return scipy.stats.weibull_min(shape, loc=location, scale=scale), 1
    return scipy.stats.weibull_min(shape, loc=-location, scale=scale), -1  # X = -Y


@pytest.mark.parametrize("model, location, scale, shape", [
    ("gaussian", 1e-7, 2e-8, 0.0),
    ("weibull_tail", -3e-8, 5e-8, 1.6),
    ("weibull_bounded", 4e-8, 5e-8, 0.8),
])
def test_distributions_against_scipy(model, location, scale, shape):
    distribution = topography.HeightDistribution(model, location, scale, shape)
    reference, sign = scipy_reference(model, location, scale, shape)
    p = np.array([1e-6, 0.01, 0.3, 0.5, 0.9, 0.999])
    x = distribution.quantile(p)
    assert x.shape == p.shape
    expected_x = reference.ppf(p) if sign > 0 else -reference.ppf(1 - p)
    assert np.allclose(x, expected_x, rtol=1e-9, atol=1e-22)
    expected_cdf = reference.cdf(x) if sign > 0 else reference.sf(-x)
    assert np.allclose(distribution.cdf(x), expected_cdf, rtol=1e-9)
    expected_pdf = reference.pdf(sign * x)
    assert np.allclose(distribution.pdf(x.reshape(2, 3)).ravel(), expected_pdf, rtol=1e-9)
    assert np.allclose(distribution.log_pdf(x), np.log(expected_pdf), rtol=1e-10)
    assert np.allclose(np.exp(distribution.log_sf(x)), 1 - expected_cdf, rtol=1e-8)
    assert np.allclose(np.exp(distribution.log_cdf(x)), expected_cdf, rtol=1e-9)
    assert type(distribution.cdf(float(x[2]))) is float
    assert math.isclose(distribution.mean(), sign * reference.mean(), rel_tol=1e-10)
    assert math.isclose(distribution.standard_deviation(), reference.std(), rel_tol=1e-10)


@pytest.mark.parametrize("model", ["gaussian", "weibull_tail", "weibull_bounded"])
def test_distribution_functions_answer_bad_arguments_by_value(model):
    # a library threw through noexcept here: the interpreter was aborted
    distribution = topography.HeightDistribution(model, 0.0, 1.0, 1.7)
    p = np.array([0.0, 1.0, -0.5, 1.5, np.nan, np.inf])
    assert np.isnan(distribution.quantile(p)).all()
    assert math.isnan(distribution.quantile(0.0)) and math.isnan(distribution.quantile(1.0))
    assert np.isfinite(distribution.quantile(np.array([5e-324, 0.5, 1 - 2 ** -53]))).all()
    for scale in (0.0, -1.0, math.inf, math.nan):
        bad = topography.HeightDistribution(model, 0.0, scale, 1.7)
        assert math.isnan(bad.mean()) and math.isnan(bad.standard_deviation()) and math.isnan(bad.quantile(0.5))
    if model == "gaussian":
        return
    for shape in (0.0, -0.5, -1.0, math.inf, math.nan):
        bad = topography.HeightDistribution(model, 0.0, 1.0, shape)
        assert math.isnan(bad.mean()) and math.isnan(bad.standard_deviation()) and math.isnan(bad.quantile(0.5))
    tiny = topography.HeightDistribution(model, 0.0, 1.0, 1e-3)  # Gamma(1001): beyond any double
    assert tiny.mean() == (math.inf if model == "weibull_tail" else -math.inf) and tiny.standard_deviation() == math.inf
    # Gamma(1 + 1/a) overflows, the mean scale * 256! does not: against Python's exact factorial
    small = topography.HeightDistribution(model, 0.0, 1e-300, 2.0 ** -8)
    mean = float(Fraction(math.factorial(256), 10 ** 300))  # 1e-300 256!, exact then rounded once
    assert math.isclose(abs(small.mean()), mean, rel_tol=1e-12)


@pytest.mark.parametrize("model, shape", [("weibull_tail", 1.5), ("weibull_bounded", 2.5), ("weibull_tail", 0.8)])
def test_fits_recover_known_shapes(model, shape):
    truth = topography.HeightDistribution(model, 2e-8, 1e-8, shape)
    sample = topography.draw_sample(truth, 3000, seed=11)
    assert sample.shape == (3000,) and np.array_equal(sample, topography.draw_sample(truth, 3000, seed=11))
    np.random.default_rng(0).shuffle(sample)  # any order
    fit = topography.fit_height_distribution(model, sample)
    assert fit.distribution.model == topography.HeightModel.__members__[model] and not fit.shape_at_bound
    assert abs(fit.distribution.shape - shape) < 0.1 * shape
    assert math.isclose(fit.objective, topography.mean_log_spacing(fit.distribution, sample), rel_tol=1e-9)
    gaussian = topography.fit_height_distribution(topography.HeightModel.gaussian, sample)
    assert math.isclose(gaussian.distribution.location, np.mean(sample), rel_tol=1e-9)
    assert math.isclose(gaussian.distribution.scale, np.std(sample), rel_tol=1e-9)
    assert topography.anderson_darling(fit.distribution, sample) < topography.anderson_darling(
        gaussian.distribution, sample)
    assert 0 < topography.kolmogorov_smirnov(fit.distribution, sample) < 0.05
    assert math.isfinite(topography.log_likelihood(fit.distribution, sample))
    with pytest.raises(asperity.Error):
        topography.fit_height_distribution(model, [1.0, 2.0, 3.0])  # too few values
    with pytest.raises(ValueError, match="unknown height model"):
        topography.fit_height_distribution("weibull", sample)


def test_assess_sample_gives_evidence_and_a_verdict():
    sample = topography.draw_sample(topography.HeightDistribution("weibull_tail", 0.0, 1e-8, 1.0), 400, seed=2)
    options = topography.AssessmentOptions(bootstrap=39, seed=3, threads=2)
    assessment = topography.assess_sample("exponential", sample, options)
    assert assessment.name == "exponential" and assessment.n == 400 and len(assessment.models) == 3
    assert [m.fit.distribution.model for m in assessment.models] == list(topography.HeightModel.__members__.values())
    gaussian = assessment.model("gaussian")
    assert gaussian.rejected and gaussian.anderson_darling_p == 1 / 40  # no refit as extreme
    weibull = assessment.model(topography.HeightModel.weibull_tail)
    assert 0 < weibull.anderson_darling_p <= 1 and not weibull.rejected
    assert weibull.shape.lo < 1.0 < weibull.shape.hi and weibull.bootstrap == 39
    assert assessment.verdict.gaussian_rejected and assessment.verdict.best != topography.HeightModel.gaussian
    assert assessment.verdict.text and assessment.verdict.aic_gain_over_gaussian > 0
    again = topography.assess_sample("exponential", sample, options)  # reproducible
    assert again.model("weibull_tail").anderson_darling_p == weibull.anderson_darling_p


# ---- synthetic surfaces ----

def test_gaussian_random_field_and_weibull_marginals():
    spectrum = [topography.SpectrumComponent(correlation=3.0, variance=1.0)]
    field = topography.gaussian_random_field(192, 160, 1e-6, 1e-6, spectrum, seed=4)
    assert (field.nx, field.ny, field.format) == (192, 160, "synthetic")
    moments = topography.spectral_moments(field)
    expected = topography.expected_spectral_moments(1e-6, 1e-6, spectrum)
    assert abs(moments.m0 / expected.m0 - 1) < 0.15 and abs(moments.m2 / expected.m2 - 1) < 0.15
    same = topography.gaussian_random_field(192, 160, 1e-6, 1e-6, spectrum, seed=4)
    assert np.array_equal(same.heights, field.heights)
    topography.to_weibull_marginal(field, 1.5, bounded=False)
    heights = field.heights
    assert heights.min() >= 0 and abs(np.mean(heights) / math.gamma(1 + 1 / 1.5) - 1) < 0.1
    topography.to_weibull_marginal(same, 1.5, bounded=True)
    assert same.heights.max() <= 0


def test_field_sizes_are_checked():
    spectrum = [topography.SpectrumComponent(2.0, 1.0)]
    for nx, ny in ((2 ** 63, 4), (2 ** 62, 4), (4, 2 ** 63), (2 ** 32, 2 ** 32), (2 ** 13 + 1, 2 ** 13)):
        with pytest.raises(asperity.Error, match="more than 67108864"):  # nx ny wrapped: a buffer overrun
            topography.gaussian_random_field(nx, ny, 1e-6, 1e-6, spectrum)
    for nx in (-1, 2 ** 64, 2 ** 200):
        with pytest.raises(ValueError, match="nx must be a whole number"):
            topography.gaussian_random_field(nx, 8, 1e-6, 1e-6, spectrum)
    with pytest.raises(TypeError):
        topography.gaussian_random_field(8.5, 8, 1e-6, 1e-6, spectrum)
    with pytest.raises(asperity.Error, match="3 x 3"):
        topography.gaussian_random_field(2, 8, 1e-6, 1e-6, spectrum)
    for correlation in (0.0, -1.0, math.nan, math.inf, 1e300, 65536.5):
        with pytest.raises(asperity.Error, match="correlation"):
            topography.gaussian_random_field(8, 8, 1e-6, 1e-6, [topography.SpectrumComponent(correlation, 1.0)])
        with pytest.raises(asperity.Error, match="correlation"):
            topography.expected_spectral_moments(1e-6, 1e-6, [topography.SpectrumComponent(correlation, 1.0)])
    for variance in (0.0, math.inf, math.nan):
        with pytest.raises(asperity.Error, match="variance"):
            topography.gaussian_random_field(8, 8, 1e-6, 1e-6, [topography.SpectrumComponent(2.0, variance)])
    with pytest.raises(asperity.Error, match="total variance"):
        topography.gaussian_random_field(8, 8, 1e-6, 1e-6, [topography.SpectrumComponent(2.0, 1e308)] * 2)
    for dx in (0.0, -1e-6, math.nan, math.inf):
        with pytest.raises(asperity.Error, match="sampling intervals"):
            topography.gaussian_random_field(8, 8, dx, 1e-6, spectrum)
    with pytest.raises(asperity.Error, match="points of noise"):  # a kernel far wider than the map
        topography.gaussian_random_field(8, 8, 1e-6, 1e-6, [topography.SpectrumComponent(65536.0, 1.0)])
    with pytest.raises(asperity.Error, match="multiply-adds"):
        topography.gaussian_random_field(4096, 4096, 1e-6, 1e-6, [topography.SpectrumComponent(500.0, 1.0)])
    with pytest.raises(asperity.Error, match="at least one component"):
        topography.gaussian_random_field(8, 8, 1e-6, 1e-6, [])
    assert topography.gaussian_random_field(3, 3, 1e-6, 1e-6, spectrum).heights.shape == (3, 3)
    assert topography.gaussian_random_field(np.int64(4), np.uint8(3), 1e-6, 1e-6, spectrum).heights.shape == (3, 4)
    field = topography.gaussian_random_field(5, 4, 1e-6, 1e-6, spectrum)
    for factor in (2 ** 63, 2 ** 64 - 1):  # ceil(n / factor) wrapped: a 0 x 0 map holding one height
        assert topography.decimated(field, factor).heights.shape == (1, 1)


def test_options_that_set_the_work_are_bounded():
    field = topography.gaussian_random_field(96, 96, 1e-6, 1e-6, [topography.SpectrumComponent(2.0, 1e-16)], seed=9)
    for points in (2 ** 31 - 1, 100001, 1, 0, -5):
        contact = topography.ContactOptions(1e11, curve_points=points, table_path=asperity.Table.default_path())
        with pytest.raises(asperity.Error, match="curve_points must be from 2 to 100000"):
            topography.analyse_height_map(field, assessment=topography.AssessmentOptions(bootstrap=0),
                                          fit_heights=False, contact=contact)
    contact = topography.ContactOptions(1e11, curve_points=2, table_path=asperity.Table.default_path())
    analysis = topography.analyse_height_map(field, assessment=topography.AssessmentOptions(bootstrap=0),
                                             fit_heights=False, contact=contact)
    assert analysis.contact.find("gaussian").curve.pressure.size == 2
    sample = topography.draw_sample(topography.HeightDistribution(), 50)
    for bootstrap in (2 ** 31 - 1, 100001, -1):
        with pytest.raises(asperity.Error, match="bootstrap must be from 0 to 100000"):
            topography.assess_sample("x", sample, topography.AssessmentOptions(bootstrap=bootstrap))


# ---- the whole path ----

def test_analyse_the_real_afm_map(tmp_path):
    contact = topography.ContactOptions(2e9, pressures=[1e5], table_path=asperity.Table.default_path(), threads=2)
    options = topography.AnalysisOptions(assessment=topography.AssessmentOptions(bootstrap=40, threads=2),
                                         summits=topography.SummitOptions(window=2), fit_heights=False,
                                         contact=contact)
    analysis = topography.analyse_surface_file(AFM, options)
    document = analysis.to_dict()
    assert document["schema"] == topography.SURFACE_JSON_SCHEMA == "asperity-surface/3" and json.loads(analysis.json()) == document
    assert document["surface"]["nx"] == 256 and analysis.map.heights.shape == (256, 256) and analysis.leveled
    summits = analysis.summits
    assert document["summits"]["count"] == len(summits) == summits.heights.size > 5
    assert document["summits"]["window_points"] == 2
    assert math.isclose(document["summits"]["radius_m"], summits.radius, rel_tol=1e-12)
    assert analysis.heights is None and len(analysis.summit_heights.models) == 3
    verdict = document["fits"]["summit_heights"]["verdict"]
    assert verdict["best"] == analysis.summit_heights.verdict.best.name.replace("_", "-")
    comparison = analysis.contact
    assert comparison is not None and math.isclose(comparison.nominal_area, analysis.map.width * analysis.map.length)
    # the exact contact, the referee, by default on a map of at most EXACT_AUTO_MAX_POINTS (issue 40)
    assert contact.exact is None and 256 * 256 <= topography.EXACT_AUTO_MAX_POINTS == 512 * 512
    assert [m.label for m in comparison.models] == ["measured-summits", "measured-summits-own-radii", "gaussian-moments",
                                                   "gaussian", "weibull-tail", "weibull-bounded", "persson", "exact"]
    assert document["contact"]["references"]["exact"] is True
    assert comparison.exact_headline.startswith("Against the exact elastic contact of the map at 1e+05 Pa: closest ")
    never = topography.ContactOptions(2e9, exact=False)
    assert never.exact is False and topography.ContactOptions(2e9, exact=True).exact is True
    gaussian = comparison.find("gaussian")
    assert gaussian.served and comparison.find("nonsense") is None
    curve = gaussian.curve
    assert isinstance(curve, asperity.PhysicalState) and curve.pressure.size == 61
    assert np.all(np.diff(curve.pressure) > 0) and np.all(np.diff(curve.stiffness) > 0)
    assert math.isclose(gaussian.at_pressures.pressure[0], 1e5, rel_tol=1e-9)
    # the model's state is the library's: a ContactModel of the same surface at that pressure
    model = asperity.ContactModel(asperity.Table.open_default(), gaussian.surface)
    assert math.isclose(model.at_pressure(1e5).stiffness, gaussian.at_pressures.stiffness[0], rel_tol=1e-9)
    assert "summits" in analysis.summary()
    # how many measured summits carry the answer, and no closest model where too few do (issue 40)
    counts = comparison.measured_summits_in_contact
    assert counts == document["contact"]["measured_summits_in_contact"] and len(counts) == 1
    assert comparison.compared_at_pressures == [counts[0] >= topography.MIN_SUMMITS_TO_COMPARE]
    assert document["contact"]["min_measured_summits_to_compare"] == topography.MIN_SUMMITS_TO_COMPARE == 25
    if not comparison.compared_at_pressures[0]:
        assert comparison.closest == "" and "too few to compare models" in comparison.headline
    # each sample's intervals say the method that made them
    for m in analysis.summit_heights.models:
        assert m.shape_interval == "centred-on-estimate"
        assert m.interval_method == document["fits"]["summit_heights"]["intervals"]

    outcome = analysis.write_report(tmp_path / "report")
    assert outcome.plots and outcome.plot_note == ""
    names = {Path(f).name for f in outcome.files}
    assert names == {"report.md", "report.json", "curves.csv", "summits.csv", "fits.svg", "contact.svg"}
    assert json.loads((tmp_path / "report" / "report.json").read_text())["schema"] == topography.SURFACE_JSON_SCHEMA
    same = topography.write_report(analysis, str(tmp_path / "again"))
    assert len(same.files) == len(outcome.files)


def test_analyse_the_real_x3p_map_with_keywords():
    analysis = topography.analyse_surface_file(X3P, assessment=topography.AssessmentOptions(bootstrap=0),
                                               fit_heights=False, sampling_factors=[1])
    assert len(analysis.summits) == 2482  # as `asperity surface` finds (test_topography_cli)
    assert analysis.contact is None and [row.factor for row in analysis.sampling] == [1]
    assert analysis.options.assessment.bootstrap == 0


def test_analyse_a_synthetic_map_leaves_it_unchanged():
    field = topography.gaussian_random_field(96, 96, 1e-6, 1e-6, [topography.SpectrumComponent(2.0, 1e-16)], seed=9)
    before = field.heights.copy()
    analysis = topography.analyse_height_map(field, topography.AnalysisOptions(
        assessment=topography.AssessmentOptions(bootstrap=0), fit_heights=False))
    assert np.array_equal(field.heights, before)
    assert analysis.statistics.valid_points == 96 * 96 and analysis.moments.alpha > 1
    with pytest.raises(TypeError):
        topography.analyse_height_map(field, topography.AnalysisOptions(), level=False)
    flat = topography.HeightMap(np.zeros((10, 10)), 1e-6, 1e-6)
    floor = topography.analyse_height_map(flat).noise_floor
    assert floor.reached and "no roughness" in floor.text


# ---- documentation: docstrings for help(), stubs for editors ----

def public_names():
    return {name for name in dir(topography) if not name.startswith("_")}


def test_docstrings():
    for name in public_names():
        item = getattr(topography, name)
        if callable(item):
            assert item.__doc__, name
    for function in (topography.read_height_map, topography.analyse_surface_file, topography.fit_height_distribution,
                     topography.find_summits, topography.gaussian_random_field, topography.write_report):
        assert len(function.__doc__) > 80, function.__name__


def test_stubs_name_what_the_submodule_holds():
    stub = ast.parse((Path(asperity.__file__).parent / "topography.pyi").read_text())
    defined = {}
    for node in stub.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            defined[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            defined[node.target.id] = node
        elif isinstance(node, ast.Assign):
            defined[node.targets[0].id] = node
    aliases = {"FloatArray", "IntArray", "PathLike", "FormatLike", "ModelLike"}
    assert public_names() == set(defined) - aliases
    for name, node in defined.items():
        if isinstance(node, ast.ClassDef):
            cls = getattr(topography, name)
            members = {item.name for item in node.body if isinstance(item, ast.FunctionDef)}
            members |= {item.target.id for item in node.body if isinstance(item, ast.AnnAssign)}
            members |= {item.targets[0].id for item in node.body if isinstance(item, ast.Assign)}
            bound = set(cls.__members__) if hasattr(cls, "__members__") else {
                m for m in dir(cls) if not m.startswith("_")}
            assert {m for m in members if not m.startswith("_")} == bound, name
            assert all(hasattr(cls, m) for m in members), name


def test_spectral_random_field():
    field = topography.spectral_random_field(128, 96, 1e-7, 1e-7, topography.CorrelationFunction.exponential, 6.0, seed=3)
    assert field.heights.shape == (96, 128)
    assert abs(float(np.var(field.heights)) - 1) < 0.2
    again = topography.spectral_random_field(128, 96, 1e-7, 1e-7, topography.CorrelationFunction.exponential, 6.0, seed=3)
    assert np.array_equal(field.heights, again.heights)
    with pytest.raises(asperity.Error):
        topography.spectral_random_field(2, 96, 1e-7, 1e-7, topography.CorrelationFunction.gaussian, 2.0)


def test_the_verdict_says_when_a_test_cannot_speak_and_when_the_side_cannot_be_told():
    """Issue 40, items 2 and 3: a smooth 64^2 map has about ten summits: its summit test is not
    applicable (with the count), and a Gaussian map tells no side; the Python record, the JSON and
    the rules' constants agree."""
    field = topography.spectral_random_field(64, 64, 1e-7, 1e-7, topography.CorrelationFunction.gaussian, 8, 7001)
    analysis = topography.analyse_height_map(field, topography.AnalysisOptions(
        assessment=topography.AssessmentOptions(bootstrap=40, threads=2), sampling_factors=[1]))
    verdict, document = analysis.verdict, analysis.to_dict()["verdict"]
    assert analysis.summit_heights.n < topography.MIN_SUMMITS_TO_TEST == 100
    assert not verdict.summit_test_applicable and document["summit_test_applicable"] is False
    assert verdict.summit_test_note == document["summit_test_note"]
    assert verdict.summit_test_note.startswith(f"not applicable: {analysis.summit_heights.n} summits")
    assert document["summit_test_min_summits"] == topography.MIN_SUMMITS_TO_TEST
    assert document["summit_test_rule"] == topography.summit_test_rule()
    assert not verdict.side_told and document["side_told"] is False and document["heights_orientation"] == "none"
    assert verdict.side_note == document["side_note"] and verdict.side_note.startswith("the side cannot be told from this map")
    assert document["side_rule"] == topography.side_rule() and "3 times" in topography.side_rule()
    assert topography.SIDE_INTERVAL_RATIO_MAX == 3
    assert "The side cannot be told from this map" in verdict.text
    assert document["model_for_contact"] in ("gaussian", "none")
