"""Plain Python threads hammering shared objects: one height map, one curve, one table, one surface,
one distribution, called from several threads at once while other threads change them (their
properties, a map's heights through the numpy view, the map in place). Whatever the interleaving,
no crash, no corrupted heap, no exception but the expected ones, and answers that are the
library's for some state the object was in. The calls that release the GIL work on copies taken
while it is held (python/src/py_*.cpp of asperity.topography); this test is what shows it, in CI under
AddressSanitizer and ThreadSanitizer (.ci/run: scripts/python-sanitizer-tests.sh).

numpy copies into an array without the GIL (the writes through a map's heights view here): a
race between such a copy and any reader of the array, numpy's own included, is numpy's, not
promised (docs/reliability.md); under ThreadSanitizer python/tests/tsan.supp ignores numpy's
copies, and every access of the module's and the library's code is checked.

ASPERITY_STRESS_SECONDS sets how long each test runs (default 1 s; the sanitizer runs take longer)."""
import copy
import os
import random
import threading
import time

import numpy as np
import pytest

import asperity
from asperity import topography

SECONDS = float(os.environ.get("ASPERITY_STRESS_SECONDS", "1"))
THREADS = 4
LARGE = 4096  # elements: above the size from which the array calls release the GIL


def hammer(operations, seconds=SECONDS, threads=THREADS):
    """Runs randomly chosen operations(rng, k) from `threads` threads for `seconds`; returns how
    many ran. An exception in any thread fails the test (raised here)."""
    errors, counts = [], [0] * threads
    start = threading.Barrier(threads)
    stop = time.monotonic() + seconds

    def work(k):
        rng = random.Random(k)
        start.wait()
        try:
            while time.monotonic() < stop and not errors:
                rng.choice(operations)(rng, k)
                counts[k] += 1
        except BaseException as error:  # noqa: B902 - reported in the main thread
            errors.append(error)

    pool = [threading.Thread(target=work, args=(k,)) for k in range(threads)]
    for thread in pool:
        thread.start()
    for thread in pool:
        thread.join()
    if errors:
        raise errors[0]
    return sum(counts)


def test_one_height_map_from_many_threads(tmp_path):
    spectrum = [topography.SpectrumComponent(2.0, 1e-16)]
    field = topography.gaussian_random_field(96, 80, 1e-6, 1e-6, spectrum, seed=5)
    original = field.heights.copy()
    lengths = topography.CorrelationLengths(2, 2)
    options = topography.AnalysisOptions(assessment=topography.AssessmentOptions(bootstrap=0), fit_heights=False,
                                         sampling_factors=[1])

    def readers(rng, k):
        choice = rng.randrange(9)
        if choice == 0:
            plane = topography.fit_plane(field)
            assert np.isfinite([plane.offset, plane.slope_x, plane.slope_y]).all()
        elif choice == 1:
            assert topography.height_statistics(field).valid_points == 96 * 80
        elif choice == 2:
            assert topography.spectral_moments(field).m0 >= 0
        elif choice == 3:
            assert topography.correlation_lengths(field).x >= 1
        elif choice == 4:
            assert topography.thinned_heights(field, lengths, 100).size <= 100
        elif choice == 5:
            topography.find_summits(field)
        elif choice == 6:
            assert topography.decimated(field, 2).nx == 48
        elif choice == 7:
            topography.write_gsf(field, tmp_path / f"map{k}.gsf")
        else:
            try:
                topography.analyse_height_map(field, options)
            except asperity.Error as error:  # the map as another thread left it may have too few summits
                assert "summits" in str(error)

    def writers(rng, k):
        choice = rng.randrange(8)
        if choice == 0:
            topography.subtract_plane(field, topography.Plane(offset=1e-12, slope_x=rng.uniform(-1e-6, 1e-6)))
        elif choice == 1:
            topography.to_weibull_marginal(field, rng.uniform(2.0, 3.0))  # pushes a note; a >= 2 keeps it finite
        elif choice == 2:
            field.heights[rng.randrange(80), :] = original[rng.randrange(80), :]  # the view: the map's storage
        elif choice == 3:
            field.heights[...] = original
        elif choice == 4:
            field.notes = [f"thread {k}"] * rng.randrange(4)
        elif choice == 5:
            field.source = f"source {k} " * rng.randrange(1, 40)  # reallocates the string
        elif choice == 6:
            field.dx, field.dy = rng.choice([(1e-6, 1e-6), (2e-6, 5e-7)])
        else:
            assert "HeightMap" in repr(copy.copy(field)) and len(field.notes) >= 0

    assert hammer([readers, readers, writers]) > 0
    assert field.heights.shape == (80, 96) and np.isfinite(field.heights).all()


def test_curves_tables_and_distributions_from_many_threads():
    table = asperity.Table.open_default()
    curve = table.curve("weibull", "tail", 1.6)
    surface = asperity.Surface(summit_count=1e4, summit_radius=1e-4, height_scale=1e-6, contact_modulus=1e11)
    model = asperity.ContactModel(table, asperity.PhysicalSurface(
        "weibull", "tail", shape=1.6, height_scale=1e-6, summit_radius=1e-4, summit_density=1e10, nominal_area=1e-4,
        contact_modulus=1e11))
    inverse = asperity.InverseCurve(curve, 3)
    law = asperity.PerssonLaw(beta=0.5)
    distribution = topography.HeightDistribution("weibull_tail", 0.0, 1e-8, 1.5)
    separations = np.linspace(-2.0, 6.0, LARGE)
    expected = curve.value(3, separations)
    sample = topography.draw_sample(distribution, 200, seed=3)

    def calls(rng, k):
        choice = rng.randrange(10)
        if choice == 0:
            assert np.array_equal(curve.value(3, separations), expected)
        elif choice == 1:  # out overlapping its own input, a thread's own buffer
            buffer = np.empty(LARGE + 3)
            given, out = (buffer[:LARGE], buffer[3:]) if rng.random() < 0.5 else (buffer[3:], buffer[:LARGE])
            given[:] = separations
            curve.value(3, given, out=out)
            assert np.array_equal(out, expected)
        elif choice == 2:
            state = asperity.contact_at(curve, surface, separations)
            assert state.load.shape == (LARGE,)
        elif choice == 3:
            assert table.curve("weibull", rng.choice(["tail", "bounded"]), rng.uniform(0.5, 20.0)).shape > 0
            assert len(table.sets) > 0
        elif choice == 4:
            assert np.isfinite(inverse.separation_at(expected[100:200])).all()
        elif choice == 5:
            assert model.at_load(np.logspace(-3, 3, LARGE)).load.shape == (LARGE,)
        elif choice == 6:
            p = distribution.pdf(np.linspace(0, 5e-8, LARGE))
            q = distribution.quantile(np.linspace(0.01, 0.99, LARGE))
            assert p.shape == q.shape == (LARGE,)
        elif choice == 7:
            assert topography.draw_sample(distribution, LARGE, seed=k).size == LARGE
        elif choice == 8:
            assert law.pressure(separations).shape == (LARGE,)
        else:
            topography.fit_height_distribution("weibull_tail", sample)

    def changes(rng, k):
        choice = rng.randrange(5)
        if choice == 0:
            surface.summit_count = rng.choice([1e4, 2e4, -1.0, float("nan")])
        elif choice == 1:
            surface.height_scale = rng.choice([1e-6, 2e-6])
        elif choice == 2:
            distribution.shape = rng.uniform(0.5, 3.0)
            distribution.scale = rng.choice([1e-8, 2e-8])
        elif choice == 3:
            law.beta = rng.uniform(0.1, 1.0)
        else:
            sample[rng.randrange(sample.size)] = rng.uniform(0, 1e-7)

    assert hammer([calls, calls, calls, changes]) > 0


def test_two_threads_one_gil_releasing_method():
    # the case: two plain threads calling one HeightMap method that released the GIL and
    # appended to the map's notes without it (on a small map the calls are short: the heap was
    # corrupted within a second)
    field = topography.gaussian_random_field(3, 3, 1e-6, 1e-6, [topography.SpectrumComponent(0.5, 1.0)], seed=1)

    def both(rng, k):
        topography.to_weibull_marginal(field, 2.0)
        if rng.random() < 1e-4:  # the notes grow by one a call: bounded
            field.notes = []

    assert hammer([both], threads=2) > 0


def test_law_curves_from_many_threads():
    # the generator runs without the GIL (python/src/law_curves.cpp): threads tabulating at once
    # get the same nodes as one alone, and readers of the curves they made run meanwhile
    keys = dict(contact_modulus=1.13e11, yield_strength=1e9, poisson=0.3, distribution="gaussian", height_scale=1e-6,
                summit_radius=1e-4, summit_density=4e8, nominal_area=1e-4, separation=(0, 2), max_rel_error=1e-4)
    alone = asperity.law_curves("kogut-etsion", **keys)
    nodes = alone.nodes["pressure"]

    def tabulate(rng, k):
        made = asperity.law_curves("kogut-etsion", **keys)
        assert np.array_equal(made.nodes["pressure"], nodes)

    def read(rng, k):
        u = rng.uniform(alone.min_separation, alone.max_separation)
        assert alone.separation_at_pressure(alone.pressure(u)) == pytest.approx(u, rel=1e-9, abs=1e-18)

    assert hammer([tabulate, read], threads=3) > 0
