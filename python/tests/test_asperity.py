"""The Python module against closed forms (docs/model.md section 5), the library's own scalar
path, and its error messages; arrays of every shape and dtype; the type stubs against the module.
Run by ctest (python_tests) with PYTHONPATH=build/python."""
import ast
import copy
import gc
import math
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import asperity

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def table():
    return asperity.Table.open_default()


@pytest.fixture(scope="module")
def weibull2(table):
    return table.curve("weibull", "tail", 2.0)


@pytest.fixture(scope="module")
def gaussian(table):
    return table.curve("gaussian", "tail")


def close(actual, expected, rel):
    return abs(actual - expected) <= rel * abs(expected)


# ---- the example, and arrays in and out ----

def test_quick_start(table):
    curve = table.curve("weibull", "bounded", 1.73)
    load = curve.value(3, np.linspace(-1.0, -0.01, 100))
    assert isinstance(load, np.ndarray) and load.dtype == np.float64 and load.shape == (100,)
    assert np.all(load > 0) and np.all(np.diff(load) < 0)  # falls toward first contact at s = 0
    assert load[0] == curve.value(3, -1.0)


def test_numbers_give_floats_arrays_give_arrays(weibull2):
    assert type(weibull2.value(3, 0.5)) is float
    assert type(weibull2.value(3, 1)) is float
    assert type(weibull2.value(3, np.float64(0.5))) is float
    assert type(weibull2.value(3, np.float32(0.5))) is float
    zero_d = weibull2.value(3, np.array(0.5))
    assert isinstance(zero_d, np.ndarray) and zero_d.shape == ()


@pytest.mark.parametrize("make", [
    lambda s: s.reshape(4, 5),
    lambda s: s.reshape(2, 2, 5),
    lambda s: np.asfortranarray(s.reshape(4, 5)),
    lambda s: s[::2],                        # not contiguous
    lambda s: s.astype(np.float32),
    lambda s: list(s),
    lambda s: s.reshape(20, 1)[:, 0],
])
def test_any_shape_and_dtype(weibull2, make):
    base = np.linspace(-1.5, 4.0, 20)
    given = make(base)
    result = weibull2.value(3, given)
    expected_shape = np.shape(given)
    assert result.shape == expected_shape
    flat_in = np.asarray(given, dtype=np.float64).ravel(order="C")
    flat_out = result.ravel(order="C")
    for s, value in zip(flat_in, flat_out):
        assert close(value, weibull2.value(3, float(s)), 1e-13)


def test_empty_array(weibull2):
    assert weibull2.value(0, np.empty((0, 3))).shape == (0, 3)


def test_batch_agrees_with_scalar_on_a_large_array(weibull2):
    separations = np.random.default_rng(1).uniform(weibull2.table_min_separation, weibull2.table_max_separation, 50000)
    logs = weibull2.log_value(3, separations)  # large: computed without the GIL
    for i in range(0, separations.size, 997):
        scalar = weibull2.log_value(3, float(separations[i]))
        assert abs(logs[i] - scalar) <= 2e-14 * (1 + abs(scalar))


def test_out_parameter(weibull2):
    s = np.linspace(0, 2, 10)
    out = np.empty(10)
    assert weibull2.value(2, s, out=out) is out
    assert np.array_equal(out, weibull2.value(2, s))
    with pytest.raises(ValueError, match="elements"):
        weibull2.value(2, s, out=np.empty(9))
    with pytest.raises(TypeError):
        weibull2.value(2, s, out=np.empty(10, dtype=np.float32))


@pytest.mark.parametrize("shift", [1, -1, 7, -4095, 4095, 9999, -9999])
def test_out_overlapping_the_input(weibull2, shift):
    # out and the input in one buffer, apart by `shift` elements: the values of separate buffers,
    # as the C API promises (the input is copied first when they overlap without being the same)
    n = 10000
    s = np.linspace(-3.0, 5.0, n)
    expected = weibull2.value(3, s)
    buffer = np.empty(n + abs(shift))
    given = buffer[max(0, -shift):][:n]
    out = buffer[max(0, shift):][:n]
    given[:] = s
    assert weibull2.value(3, given, out=out) is out
    assert np.array_equal(out, expected)
    in_place = s.copy()  # the same elements: in place
    weibull2.log_value(3, in_place, out=in_place)
    assert np.array_equal(in_place, weibull2.log_value(3, s))


def test_out_must_be_aligned(weibull2):
    raw = np.zeros(8 * 10 + 1, dtype=np.uint8)
    unaligned = raw[1:].view(np.float64)
    assert not unaligned.flags.aligned
    with pytest.raises(ValueError, match="aligned"):
        weibull2.value(3, np.zeros(10), out=unaligned)
    unaligned[:] = np.linspace(0, 1, 10)  # an unaligned input is read through an aligned copy
    assert np.array_equal(weibull2.value(3, unaligned), weibull2.value(3, np.linspace(0, 1, 10)))


@pytest.mark.parametrize("given", [None, [1.0, None], "0.5", b"0.5", ["0.5"], 1 + 2j, np.array([1 + 2j]),
                                   np.array(["2020-01-01"], dtype="datetime64[D]"), {"a": 1}, object()])
def test_only_numbers_are_separations(weibull2, given):
    # numpy would turn None into NaN, parse strings and drop an imaginary part: all refused
    with pytest.raises(TypeError, match="separation must be a number or an array of numbers"):
        weibull2.value(3, given)
    with pytest.raises(TypeError):
        asperity.contact_at(weibull2, asperity.Surface(), given)


def test_numbers_of_every_kind_are_separations(weibull2):
    from decimal import Decimal
    from fractions import Fraction
    half = weibull2.value(3, 0.5)
    assert weibull2.value(3, Fraction(1, 2)) == half and weibull2.value(3, Decimal("0.5")) == half
    assert np.array_equal(weibull2.value(3, [Fraction(1, 2), 1]), weibull2.value(3, [0.5, 1.0]))
    assert weibull2.value(3, np.array([True])) [0] == weibull2.value(3, 1.0)
    assert weibull2.value(3, np.array([1], dtype=np.uint64))[0] == weibull2.value(3, 1.0)


def test_threads_share_one_curve(weibull2):
    separations = np.linspace(-2, 8, 200000)
    expected = weibull2.value(1, separations)
    results = [None] * 4

    def work(k):
        results[k] = weibull2.value(1, separations)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for result in results:
        assert np.array_equal(result, expected)


def gil_pause_during(call):
    """The longest pause of a Python loop in this thread while another thread runs call(), as a
    fraction of the call's duration: 1 if the call holds the GIL throughout."""
    timing = {}

    def work():
        begin = time.perf_counter()
        call()
        timing["call"] = (begin, time.perf_counter())

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-4)
    stamps = []
    try:
        worker = threading.Thread(target=work)
        worker.start()
        while worker.is_alive():
            stamps.append(time.perf_counter())
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    begin, end = timing["call"]
    inside = [begin] + [t for t in stamps if begin < t < end] + [end]
    return max(b - a for a, b in zip(inside, inside[1:])) / (end - begin)


def test_large_arrays_release_the_gil(weibull2):
    separations = np.linspace(-2.0, 20.0, 6_000_000)
    assert gil_pause_during(lambda: weibull2.value(3, separations)) < 0.5
    # the check itself tells a call holding the GIL (py::vectorize does) from one releasing it.
    # A holding call's pause falls short of its whole duration only when the worker, back from
    # the call, waits for the GIL to stamp its end (two busy cores, sanitizers): the best of three
    # measurements is the instrument's reading.
    shapes = np.full(3_000_000, 2.0)
    assert max(gil_pause_during(lambda: asperity.weibull_mean(shapes)) for _ in range(3)) > 0.9


# ---- values against closed forms (docs/model.md section 5) ----

def test_enums(weibull2):
    assert weibull2.distribution == asperity.Distribution.weibull and weibull2.side.name == "tail"
    assert asperity.Side.bounded.name == "bounded" and int(asperity.Distribution.gaussian) == 1
    assert asperity.best_instruction_set() in asperity.InstructionSet.__members__.values()


def test_weibull_closed_forms(weibull2, table):
    for s in (0.0, 0.3, 1.0, 2.5, 5.0):
        assert close(weibull2.value(0, s), math.exp(-s * s), 1e-12)                      # J_0 = exp(-s^a)
        assert close(weibull2.value(2, s), math.sqrt(math.pi) / 2 * math.erfc(s), 1e-12)  # a = 2: J_1
    for a in (0.5, 1.0, 3.0, 20.0):
        curve = table.curve(asperity.Distribution.weibull, asperity.Side.tail, a)
        for twice_order in range(6):
            assert close(curve.value(twice_order, 0.0), math.gamma(1 + 0.5 * twice_order / a), 1e-12)  # moments
    exponential = table.curve("weibull", "tail", 1.0)
    assert close(exponential.value(3, 2.0), math.gamma(2.5) * math.exp(-2.0), 1e-12)  # Gamma(n+1) exp(-s)
    bounded = table.curve("weibull", "bounded", 1.6)
    for d in (0.1, 0.7, 2.0):
        assert close(bounded.value(0, -d), 1 - math.exp(-d ** 1.6), 1e-12)  # K_0 = 1 - exp(-d^a)
    assert bounded.value(3, 0.5) == 0.0 and bounded.log_value(3, 0.5) == -math.inf


def test_gaussian_closed_forms(gaussian):
    for s in (-2.0, 0.0, 0.5, 3.0):
        f0 = 0.5 * math.erfc(s / math.sqrt(2))
        phi = math.exp(-s * s / 2) / math.sqrt(2 * math.pi)
        assert close(gaussian.value(0, s), f0, 1e-12)
        assert close(gaussian.value(2, s), phi - s * f0, 1e-12)
    assert close(gaussian.value(5, 0.0), 0.616634218996844, 1e-12)  # the half-normal moment


def test_far_tail_log(weibull2):
    assert weibull2.value(0, 40.0) == 0.0               # underflows
    assert close(weibull2.log_value(0, 40.0), -1600.0, 1e-13)   # ln J_0 = -s^2


def test_bad_separations_give_nan(weibull2):
    out = weibull2.value(3, [np.nan, np.inf, -np.inf, 1.0])
    assert np.isnan(out[:3]).all() and np.isfinite(out[3])


def test_served_separations(weibull2):
    # a full table's curve serves every separation (a scene table's, its scene's range: NaN outside)
    assert weibull2.served_min_separation == -np.inf and weibull2.served_max_separation == np.inf
    assert weibull2.serves(1.0) and not weibull2.serves(np.nan)
    assert weibull2.serves([-1e300, 0.0, 1e300, np.nan]).tolist() == [True, True, True, False]


# ---- errors carry the library's message ----

def test_errors(table, weibull2, tmp_path):
    with pytest.raises(asperity.Error, match=r"shape 1000 is outside the table's range \[0.5, 20\]"):
        table.curve("weibull", "tail", 1000)
    with pytest.raises(asperity.Error, match="no bounded side"):
        table.curve("gaussian", "bounded")
    with pytest.raises(ValueError, match="unknown distribution 'weibul'"):
        table.curve("weibul", "tail", 2.0)
    with pytest.raises(ValueError, match="unknown side"):
        table.curve("weibull", "up", 2.0)
    with pytest.raises(ValueError, match="needs its shape"):
        table.curve("weibull", "tail")
    with pytest.raises(ValueError, match="twice_order 6"):
        weibull2.value(6, 0.0)
    with pytest.raises(TypeError):
        weibull2.value(3, "near")
    missing = tmp_path / "missing.h5"
    for spelled in (missing, str(missing), os.fsencode(missing)):  # PathLike, str, bytes
        with pytest.raises(asperity.Error, match=str(missing)):
            asperity.Table.open(spelled)
    with pytest.raises(ValueError, match="NUL"):  # the C library would open "missing" instead
        asperity.Table.open(str(missing) + "\0.h5")
    with pytest.raises(TypeError, match="str, bytes or os.PathLike"):
        asperity.Table.open(3)
    not_utf8 = os.fsencode(tmp_path) + b"/t\xff\xfe.h5"  # any bytes the file system holds
    with pytest.raises(asperity.Error, match=r"t\\xff\\xfe\.h5"):
        asperity.Table.open(not_utf8)
    with pytest.raises(asperity.Error, match=r"t\\xff\\xfe\.h5"):
        asperity.Table.open(os.fsdecode(not_utf8))  # the same name as str (surrogateescape)
    not_hdf5 = tmp_path / "not.h5"
    not_hdf5.write_bytes(b"not a table at all")
    with pytest.raises(asperity.Error, match="not.h5"):
        asperity.Table.open(str(not_hdf5))
    assert issubclass(asperity.Error, RuntimeError)
    # a bad value is a ValueError in every part of the module (issue 39): the library's and a typo's alike
    assert issubclass(asperity.Error, ValueError)
    with pytest.raises(ValueError, match="summit radius R must be a positive number"):
        asperity.RoughSurface("weibull", "tail", shape=2.0, height_scale=1e-6, summit_radius=-1.0, summit_density=1e10,
                              nominal_area=1e-4, contact_modulus=1e11).validate()


def run_python(code, **environment):
    env = dict(os.environ, **environment)
    return subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)


def test_default_table_search(table):
    places = asperity.Table.default_search_paths()
    assert asperity.Table.default_path() in places
    assert all(place.endswith(".h5") for place in places)
    missing = "/nonexistent/asperity/table.h5"
    result = run_python("import asperity\nasperity.Table.open_default()", ASPERITY_TABLE=missing)
    assert result.returncode != 0
    assert "ASPERITY_TABLE" in result.stderr and missing in result.stderr
    result = run_python("import asperity; print(asperity.Table.default_search_paths())", ASPERITY_TABLE=missing)
    assert result.stdout.strip() == repr([missing])


# ---- the physical layer ----

def test_contact_at(weibull2):
    surface = asperity.Surface(summit_count=1e4, summit_radius=1e-4, height_scale=1e-6, contact_modulus=1e11)
    s = np.array([-0.5, 0.0, 0.7])
    state = asperity.contact_at(weibull2, surface, s)
    assert isinstance(state, asperity.ContactState)
    x0, x12, x1, x32 = (weibull2.value(k, s) for k in range(4))
    assert np.allclose(state.count, 1e4 * x0, rtol=1e-13, atol=0)
    assert np.allclose(state.area, math.pi * 1e4 * 1e-4 * 1e-6 * x1, rtol=1e-13, atol=0)
    assert np.allclose(state.load, 4 / 3 * 1e4 * 1e11 * 1e-2 * 1e-9 * x32, rtol=1e-13, atol=0)
    assert np.allclose(state.stiffness, 2 * 1e4 * 1e11 * 1e-2 * 1e-3 * x12, rtol=1e-13, atol=0)
    assert np.allclose(state.stiffness_ratio, 1.5 * x12 / x32, rtol=1e-13, atol=0)
    scalar = asperity.contact_at(weibull2, surface, 0.7)
    assert type(scalar.load) is float and close(scalar.load, state.load[2], 1e-15)
    bad = asperity.contact_at(weibull2, asperity.Surface(summit_count=-1), 0.0)
    assert math.isnan(bad.load)


def test_conventions(table):
    curve = table.curve("weibull", "tail", 1.6)
    mean, rms = math.gamma(1 + 1 / 1.6), math.sqrt(math.gamma(1 + 2 / 1.6) - math.gamma(1 + 1 / 1.6) ** 2)
    assert close(asperity.weibull_mean(1.6), mean, 1e-14) and close(asperity.weibull_rms(1.6), rms, 1e-14)
    t = asperity.standardized_from_origin(curve, np.array([0.0, 1.0]))
    assert np.allclose(t, (np.array([0.0, 1.0]) - mean) / rms, rtol=1e-14)
    assert np.allclose(asperity.origin_from_standardized(curve, t), [0.0, 1.0], atol=1e-14)


def test_contact_model_round_trip(table):
    surface = asperity.PhysicalSurface("weibull", "tail", shape=2.0, height_scale=1e-6, summit_radius=1e-4,
                                       summit_density=1e10, nominal_area=1e-4,
                                       contact_modulus=asperity.contact_modulus_from(2.1e11, 0.3, 2.1e11, 0.3))
    model = asperity.ContactModel(table, surface)
    loads = np.logspace(-2, 2, 9)
    state = model.at_load(loads)
    assert isinstance(state, asperity.PhysicalState)
    assert np.allclose(model.at_separation(state.separation).load, loads, rtol=1e-11, atol=0)
    assert np.allclose(state.pressure, loads / 1e-4, rtol=1e-14)
    area = model.at_real_area(state.real_area)
    assert np.allclose(area.separation, state.separation, rtol=1e-10, atol=0)
    assert close(model.at_pressure(1e4).load, 1.0, 1e-11)
    copy = model.surface
    copy.height_scale = 1.0  # a copy: the model keeps its own
    assert model.surface.height_scale == 1e-6
    with pytest.raises(asperity.Error):
        asperity.ContactModel(table, asperity.PhysicalSurface("weibull", shape=2.0, height_scale=-1.0, **PHYSICAL))


def test_physical_helpers():
    moduli = asperity.contact_modulus_from(np.array([1e11, 2e11]), 0.3, 2e11, 0.3)  # broadcasts
    assert moduli.shape == (2,)
    assert close(moduli[1], 2e11 / (2 * (1 - 0.09)), 1e-14)
    with pytest.raises(asperity.Error):
        asperity.contact_modulus_from(-1.0, 0.3, 2e11, 0.3)
    gaussian = asperity.gaussian_surface_from_moments(1e-12, 1e-4, 1e5, 1e-4, 1e11)
    assert gaussian.distribution == asperity.Distribution.gaussian
    assert close(asperity.bandwidth_alpha(1e-12, 1e-4, 1e5), 10.0, 1e-14)
    persson = asperity.PerssonLaw(beta=0.5)
    assert close(persson.pressure(1.0), math.exp(-2.0), 1e-15)
    assert persson.stiffness_over_load() == 2.0


def test_inverse_curve_holds_its_curve(table):
    own_table = asperity.Table.open_default()
    curve = own_table.curve("weibull", "tail", 2.0)
    inverse = asperity.InverseCurve(curve, 3)
    expected = curve.value(3, 0.8)
    del curve, own_table  # the inverse holds the curve's data (a shared handle), not the Python objects
    gc.collect()
    assert close(inverse.separation_at(expected), 0.8, 1e-11)
    assert np.allclose(inverse.separation_at(np.array([expected] * 3)), 0.8, rtol=1e-11)
    assert inverse.curve.value(3, 0.8) == expected and inverse.curve.shape == 2.0
    copied = copy.copy(inverse)
    del inverse
    gc.collect()
    assert close(copied.separation_at(expected), 0.8, 1e-11) and copy.deepcopy(copied).twice_order == 3
    with pytest.raises(asperity.Error):
        asperity.InverseCurve(table.curve("weibull", "tail", 2.0), 1)


def test_contact_model_copies_outlive_the_table_and_the_model():
    own_table = asperity.Table.open_default()
    model = asperity.ContactModel(own_table, asperity.PhysicalSurface("weibull", "bounded", shape=1.6, height_scale=1e-6, **PHYSICAL))
    expected = model.at_load(0.5)
    curve = model.curve
    shallow, deep = copy.copy(model), copy.deepcopy(model)
    del model, own_table
    gc.collect()
    for copied in (shallow, deep):
        state = copied.at_load(0.5)
        assert state.separation == expected.separation and state.stiffness == expected.stiffness
        assert copied.surface.shape == 1.6
    assert curve.value(3, expected.separation / 1e-6) > 0 and copy.copy(curve).shape == 1.6


# ---- the lookup grid's options, and the rms summit height ----

def test_curve_options(table):
    default = table.curve("weibull", "tail", 2.0)
    assert default.grid_intervals > 0 and 0 <= default.grid_error <= 1e-13
    coarse = table.curve("weibull", "tail", 2.0, options=asperity.CurveOptions(grid_tolerance=1e-7))
    assert coarse.grid_intervals < default.grid_intervals and coarse.memory_bytes < default.memory_bytes
    assert coarse.grid_error <= 1e-7
    s = np.linspace(-3.0, 6.0, 1001)
    for twice_order in range(6):
        assert np.allclose(coarse.log_value(twice_order, s), default.log_value(twice_order, s), rtol=0, atol=2e-7)
    # a grid over part of the range: the table's own layout answers elsewhere, to its accuracy
    partial = table.curve("weibull", "bounded", 1.73, asperity.ALL_ORDERS,
                          options=asperity.CurveOptions(grid_min_separation=-1.0, grid_max_separation=-0.1))
    between = table.curve("weibull", "bounded", 1.73)
    s = np.linspace(-3.0, -0.001, 500)
    assert np.allclose(partial.value(3, s), between.value(3, s), rtol=1e-11, atol=0)
    options = asperity.CurveOptions()
    assert options.grid_tolerance == 1e-13 and options.grid_min_separation == -math.inf
    assert "grid_tolerance=1e-13" in repr(options)
    with pytest.raises(asperity.Error):
        table.curve("weibull", "tail", 2.0, options=asperity.CurveOptions(grid_min_separation=1.0,
                                                                          grid_max_separation=0.0))


def test_direct_curve(table):
    """Table.direct_curve: the nodes answered without a grid, within curve()'s grid tolerance of it."""
    s = np.concatenate([np.linspace(-4.0, 6.0, 1001), [-1e-300, 0.0, 1e-300, 40.0]])
    for side, shape in (("tail", 1.73), ("tail", 2.0), ("bounded", 7.1)):
        grid, direct = table.curve("weibull", side, shape), table.direct_curve("weibull", side, shape)
        assert direct.grid_intervals == 0 and direct.shape == shape
        for twice_order in range(6):
            a, b = grid.log_value(twice_order, s), direct.log_value(twice_order, s)
            finite = np.isfinite(a)
            assert np.array_equal(np.isfinite(b), finite) and np.array_equal(a[~finite], b[~finite])
            assert np.all(np.abs(a[finite] - b[finite]) <= 2e-13 * (1 + np.abs(a[finite])))
    gaussian = table.direct_curve("gaussian")
    assert gaussian.value(3, 0.5) == pytest.approx(table.curve("gaussian").value(3, 0.5), rel=1e-12)
    only_load = table.direct_curve("weibull", "tail", 2.5, 1 << 3)
    assert math.isnan(only_load.value(0, 0.5)) and only_load.value(3, 0.5) > 0
    with pytest.raises(asperity.Error, match="outside the table's range"):
        table.direct_curve("weibull", "tail", 1e3)
    with pytest.raises(ValueError, match="needs its shape"):
        table.direct_curve("weibull", "tail")


def test_height_scale_from_rms():
    c2 = math.sqrt(1 - math.pi / 4)  # a = 2: Gamma(2) - Gamma(3/2)^2
    assert close(asperity.height_scale_from_rms("weibull", 2.0, 1e-6), 1e-6 / c2, 1e-14)
    assert close(asperity.height_scale_from_rms(asperity.Distribution.weibull, 1.6, 5e-7), 8.715e-7, 1e-4)
    assert asperity.height_scale_from_rms("gaussian", 2.0, 3e-7) == 3e-7
    scales = asperity.height_scale_from_rms("weibull", np.array([1.0, 2.0]), 1e-6)  # broadcasts
    assert scales.shape == (2,) and close(scales[0], 1e-6, 1e-14) and close(scales[1], 1e-6 / c2, 1e-14)
    for shape, rms in ((2.0, 0.0), (2.0, -1e-6), (0.0, 1e-6), (2.0, math.nan)):
        with pytest.raises(asperity.Error):
            asperity.height_scale_from_rms("weibull", shape, rms)
    with pytest.raises(ValueError):
        asperity.height_scale_from_rms("weibul", 2.0, 1e-6)


def test_physical_surface_from_its_rms(table):
    surface = asperity.PhysicalSurface("weibull", "tail", shape=1.6, rms=5e-7, **PHYSICAL)
    assert close(surface.height_scale, asperity.height_scale_from_rms("weibull", 1.6, 5e-7), 1e-15)
    assert close(surface.rms, 5e-7, 1e-14)
    surface.rms = 1e-6
    assert close(surface.height_scale, 2 * asperity.height_scale_from_rms("weibull", 1.6, 5e-7), 1e-14)
    gaussian = asperity.PhysicalSurface("gaussian", rms=2e-7, **PHYSICAL)
    assert gaussian.height_scale == 2e-7 and gaussian.rms == 2e-7
    with pytest.raises(ValueError, match="once"):
        asperity.PhysicalSurface("weibull", shape=2.0, height_scale=1e-6, rms=1e-6, **PHYSICAL)
    with pytest.raises(asperity.Error):
        asperity.PhysicalSurface("weibull", shape=2.0, rms=-1.0, **PHYSICAL)
    # the model of `asperity contact --rms 5e-7 --shape 1.6` (Weibull scale 8.715e-7 m)
    model = asperity.ContactModel(table, asperity.PhysicalSurface("weibull", shape=1.6, rms=5e-7, summit_radius=1e-4,
                                                                   summit_density=1e10, nominal_area=1e-4,
                                                                   contact_modulus=1e11))
    assert close(model.surface.height_scale, 8.715e-7, 1e-4)


# ---- scenes ----

SCENE = """
name = "test"
max_rel_error = 1e-8
[[curve]]
distribution = "weibull"
shape = 1.73
side = "bounded"
quantities = ["load", "stiffness"]
separation = [-2.0, -0.01]
"""


def test_scenes(table):
    scene = asperity.parse_scene(SCENE, "inline")
    assert scene.name == "test" and scene.curves[0].twice_orders == [1, 3]
    served = asperity.serve_scene(table, scene)
    assert len(served) == 1
    view = served[0]
    direct = table.curve("weibull", "bounded", 1.73)
    assert close(view.curve.value(3, -0.4), direct.value(3, -0.4), 1e-14)
    assert math.isnan(view.curve.value(0, -0.4))  # an order the scene did not ask for
    assert view.error_bound <= 1e-8
    assert asperity.read_scene_file(REPO / "tables" / "scenes" / "bearing.toml").curves
    with pytest.raises(asperity.Error, match="shap"):
        asperity.parse_scene('[[curve]]\nshap = 1.73\n', "bad.toml")
    assert asperity.quantity_twice_order("load") == 3
    assert close(asperity.separation_at_load(direct, direct.value(3, -0.4)), -0.4, 1e-9)


# ---- documentation: docstrings for help(), stubs for editors ----

def public_names():
    return set(asperity.__all__)


def test_docstrings():
    for name in public_names():
        item = getattr(asperity, name)
        if callable(item):
            assert item.__doc__, name
    assert "twice_order" in asperity.Curve.value.__doc__
    for method in ("value", "log_value", "curve", "open_default", "at_load"):
        owner = asperity.Table if method in ("curve", "open_default") else (
            asperity.ContactModel if method == "at_load" else asperity.Curve)
        assert len(getattr(owner, method).__doc__) > 40, method


def test_stubs_name_what_the_module_holds():
    stub = ast.parse((Path(asperity.__file__).parent / "__init__.pyi").read_text())
    defined = {}
    for node in stub.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            defined[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            defined[node.target.id] = node
        elif isinstance(node, ast.ImportFrom) and node.module is None:  # from . import topography
            for alias in node.names:
                defined[alias.asname or alias.name] = node
    aliases = {"FloatArray", "PathLike", "DistributionLike", "SideLike", "QuantityName", "OrderLike", "_LawCurvesKeywords"}
    assert public_names() | {"__version__"} == set(defined) - aliases
    for name, node in defined.items():
        if name in aliases:  # the stubs' own types (_LawCurvesKeywords: checked by test_stubs)
            continue
        if isinstance(node, ast.ClassDef) and not issubclass(getattr(asperity, name), (tuple, BaseException)):
            members = {item.name for item in node.body if isinstance(item, ast.FunctionDef)}
            members |= {item.target.id for item in node.body if isinstance(item, ast.AnnAssign)}
            members |= {item.targets[0].id for item in node.body if isinstance(item, ast.Assign)}
            cls = getattr(asperity, name)
            if hasattr(cls, "__members__"):  # an enum: its values
                bound = set(cls.__members__)
            else:
                bound = {m for m in dir(cls) if not m.startswith("_")}
            assert {m for m in members if not m.startswith("_")} == bound, name
            assert all(hasattr(cls, m) for m in members), name  # __copy__, __deepcopy__ too


def test_fe_export_card_from_python(table):
    # the card the command writes (asperity contact --export), from the library: each point on the law
    model = asperity.ContactModel(table, asperity.PhysicalSurface("weibull", shape=2.0, height_scale=1e-6, summit_radius=1e-4,
                                                                   summit_density=1e10, nominal_area=1e-4,
                                                                   contact_modulus=1.15e11))
    card = model.pressure_overclosure_card(1e3, 1e8, 1e-3, "calculix", "si", "from Python",
                                           overclosure_datum="mean-summit")
    lines = card.splitlines()
    start = lines.index("*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=TABULAR")
    points = [tuple(map(float, line.split(","))) for line in lines[start + 1:] if line and line[0] in "-0123456789"]
    assert points[0][0] == 0 and len(points) > 5
    with pytest.warns(asperity.AreaFractionWarning):  # at the origin: far past GW's validity, only the datum used
        origin_to_mean = -model.at_separation(0.0).mean_separation
    for pressure, overclosure in points[1:]:
        state = model.at_separation(origin_to_mean - overclosure)
        assert abs(state.pressure - pressure) <= 1e-9 * pressure
    assert "from Python" in card
    with pytest.raises(asperity.Error, match="card format"):
        model.pressure_overclosure_card(1e3, 1e8, format="nastran")
    tabulated = asperity.tabulated_pressure_overclosure_card([0.0, 1e6, 1e7], [-2e-6, -1e-6, -5e-7], "abaqus")
    assert "1000000,-1e-06" in tabulated
    with pytest.raises(asperity.Error):
        asperity.tabulated_pressure_overclosure_card([1e6], [-1e-6])


def test_input_checks_from_python():
    assert asperity.contact_modulus_given() is None
    assert asperity.contact_modulus_given(1e11) == 1e11
    assert asperity.contact_modulus_given(young1=2.1e11, poisson1=0.3, young2=2.1e11, poisson2=0.3) == \
        asperity.contact_modulus_from(2.1e11, 0.3, 2.1e11, 0.3)
    with pytest.raises(asperity.Error, match="not both"):
        asperity.contact_modulus_given(1e11, 2.1e11, 0.3, 2.1e11, 0.3)
    with pytest.raises(asperity.Error, match="go together"):
        asperity.contact_modulus_given(young1=2.1e11)
    assert asperity.nominal_pressure_from_load(10.0, 1e-4) == 1e5
    with pytest.raises(asperity.Error):
        asperity.nominal_pressure_from_load(-1.0, 1e-4)


# ---- a new user's small frictions (issue 32): named orders, the area-fraction warning, the Gaussian's shape ----

def test_orders_by_name(table, weibull2):
    s = np.linspace(-1.5, 0.5, 7)
    for name in ("count", "stiffness", "area", "load", "F2", "F5/2", "F3/2", "I1"):
        twice_order = asperity.quantity_twice_order(name)  # the one definition (scene files use it too)
        assert twice_order >= 0, name
        assert np.array_equal(weibull2.value(name, s), weibull2.value(twice_order, s))
        assert np.array_equal(weibull2.log_value(name, s), weibull2.log_value(twice_order, s))
        assert weibull2.has_order(name) == weibull2.has_order(twice_order)
        assert asperity.order_of(name) == twice_order / 2
    assert weibull2.value("load", 0.0) == weibull2.value(3, 0.0)
    assert weibull2.value(np.int64(3), 0.0) == weibull2.value(3, 0.0)  # numpy's integers too
    inverse = asperity.InverseCurve(weibull2, "load")
    assert inverse.twice_order == 3
    assert close(inverse.separation_at(weibull2.value("load", -0.5)), -0.5, 1e-9)


def test_orders_by_name_refused_clearly(weibull2):
    with pytest.raises(ValueError, match=r"unknown order 'pressure': expected 'count', 'stiffness', 'area', 'load'"):
        weibull2.value("pressure", 0.0)
    with pytest.raises(ValueError, match="unknown order 'Load'"):  # names are exact, as in scene files
        weibull2.value("Load", 0.0)
    for wrong, kind in ((1.5, "float"), (None, "NoneType"), (True, "bool"), ([3], "list")):
        with pytest.raises(TypeError, match=f"twice_order 0..5 \\(an int\\) or a quantity's name .*not '{kind}'"):
            weibull2.value(wrong, 0.0)
    with pytest.raises(ValueError, match="twice_order 6 is outside 0..5"):
        weibull2.value(6, 0.0)
    with pytest.raises(ValueError, match="twice_order -1 is outside 0..5"):
        asperity.order_of(-1)
    with pytest.raises(ValueError, match="unknown order 'loads'"):
        asperity.InverseCurve(weibull2, "loads")
    with pytest.raises(asperity.Error):  # the inverse of the count is refused by the library, as for 0
        asperity.InverseCurve(weibull2, "count")


def model_of(table, nominal_area=1e-4):
    surface = asperity.RoughSurface("weibull", "tail", shape=2.0, height_scale=1e-6, summit_radius=1e-4,
                                    summit_density=1e10, nominal_area=nominal_area, contact_modulus=1e11)
    return asperity.ContactModel(table, surface)


def test_area_fraction_warning(table):
    import warnings

    assert issubclass(asperity.AreaFractionWarning, UserWarning)
    assert asperity.gw_area_fraction_limit == 0.1  # the command's (asperity contact), one definition
    model = model_of(table)
    area = model.surface.nominal_area
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model.at_real_area(0.05 * area)                      # within GW: no warning
        model.at_real_area(np.array([0.01, 0.09]) * area)
        model.at_separation(np.nan)
        model.at_load(np.array([np.nan, 1.0]))
    assert [w for w in caught if issubclass(w.category, asperity.AreaFractionWarning)] == []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        state = model.at_real_area(np.array([0.01, 0.2]) * area)   # one element past the limit
    found = [w for w in caught if issubclass(w.category, asperity.AreaFractionWarning)]
    assert len(found) == 1
    message = str(found[0].message)
    assert "reaches 0.2 of the nominal area (above 0.1)" in message and "impossible" not in message
    assert found[0].filename == __file__  # pointed at the caller's line
    assert np.allclose(state.area_fraction, [0.01, 0.2], rtol=1e-9)  # the answer is still given
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", asperity.AreaFractionWarning)
        past = model.at_real_area(0.3 * area)
    for query, value in ((model.at_load, past.load), (model.at_pressure, past.pressure),
                         (model.at_separation, past.separation)):
        with pytest.warns(asperity.AreaFractionWarning, match="reaches 0.3 of"):
            query(value)
    with pytest.warns(asperity.AreaFractionWarning, match="above 1 the answer is impossible"):
        model.at_real_area(2 * area)
    with pytest.warns(asperity.AreaFractionWarning):  # the FE card up to a pressure past the limit, as the command
        model.pressure_overclosure_card(1e3, 2 * past.pressure)
    with warnings.catch_warnings():
        warnings.simplefilter("error", asperity.AreaFractionWarning)   # as an exception when asked
        with pytest.raises(asperity.AreaFractionWarning):
            model.at_real_area(0.5 * area)
        model.at_real_area(0.05 * area)


PHYSICAL = dict(summit_radius=1e-4, summit_density=1e10, nominal_area=1e-4, contact_modulus=1e11)


def test_gaussian_surface_takes_no_shape(table):
    for surface in (asperity.PhysicalSurface("gaussian", shape=None, rms=5e-7, **PHYSICAL),
                    asperity.RoughSurface("gaussian", shape=None, rms=5e-7, **PHYSICAL),
                    asperity.RoughSurface("gaussian", rms=5e-7, **PHYSICAL),
                    asperity.RoughSurface("gaussian", shape=7.0, rms=5e-7, **PHYSICAL)):   # ignored, as Table.curve ignores it
        assert surface.distribution == asperity.Distribution.gaussian and surface.height_scale == 5e-7
        model = asperity.ContactModel(table, surface)
        assert model.curve.distribution == asperity.Distribution.gaussian
        assert model.at_load(1.0).load == pytest.approx(1.0, rel=1e-11)
    with pytest.raises(ValueError, match="a Weibull surface needs its shape"):
        asperity.RoughSurface("weibull", shape=None, rms=5e-7, **PHYSICAL)
    # the repr shows what applies: no side and no shape for the Gaussian
    assert repr(asperity.RoughSurface("gaussian", rms=5e-7, **PHYSICAL)).startswith("RoughSurface('gaussian', height_scale=")
    assert "side='bounded', shape=3.0" in repr(asperity.RoughSurface("weibull", "bounded", shape=3.0, rms=5e-7, **PHYSICAL))


def test_rough_surface_has_no_silent_physical_defaults():
    """Issue 39: RoughSurface() was a valid surface of silent defaults (R = 1e-4 m, E* = 1e11 Pa, a = 2)."""
    with pytest.raises(TypeError):
        asperity.RoughSurface()
    with pytest.raises(ValueError, match="needs height_scale [(]or rms[)], summit_radius, summit_density, nominal_area, "
                                         "contact_modulus"):
        asperity.RoughSurface("weibull", shape=2.0)
    with pytest.raises(ValueError, match="needs contact_modulus"):
        asperity.RoughSurface("weibull", shape=2.0, rms=5e-7, summit_radius=1e-4, summit_density=1e10, nominal_area=1e-4)
    with pytest.raises(ValueError, match="no bounded side"):
        asperity.RoughSurface("gaussian", "bounded", rms=5e-7, **PHYSICAL)
    surface = asperity.RoughSurface("weibull", shape=2.0, rms=5e-7, **PHYSICAL)
    assert surface.side == asperity.Side.tail  # side None: GW's approach, as --side's default


def test_two_surface_types_say_which_is_which():
    assert asperity.PhysicalSurface is asperity.RoughSurface and asperity.Surface is asperity.SurfaceScales
    assert "ContactModel" in asperity.RoughSurface.__doc__ and "PhysicalSurface" in asperity.RoughSurface.__doc__
    assert "contact_at" in asperity.SurfaceScales.__doc__ and "RoughSurface" in asperity.SurfaceScales.__doc__
    assert "former name" in asperity.SurfaceScales.__doc__
