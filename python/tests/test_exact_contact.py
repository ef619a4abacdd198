"""asperity.topography.ExactContact: the exact elastic contact of a map from Python, against
Westergaard's wavy surface (closed forms), on the real AFM map of tests/data/surfaces/, its
fields as arrays, its errors, and one solver shared by threads (a lock, no GIL held)."""
import math
import threading
from pathlib import Path

import numpy as np
import pytest

import asperity
from asperity import topography

AFM = Path(__file__).resolve().parents[2] / "tests" / "data" / "surfaces" / "afm-zsensor-10um.txt"


def wavy(nx=256, wavelength=1e-3, amplitude=1e-6):
    x = np.arange(nx) / nx
    heights = np.tile(amplitude * np.cos(2 * math.pi * x), (4, 1))
    return topography.HeightMap(heights, wavelength / nx, wavelength / nx)


def test_westergaard_wavy_surface():
    modulus, wavelength, amplitude = 1e11, 1e-3, 1e-6
    full = math.pi * modulus * amplitude / wavelength
    solver = topography.ExactContact(wavy(), contact_modulus=modulus, tolerance=1e-10)
    for ratio in (0.1, 0.5):
        step = solver.at_pressure(ratio * full)
        assert step.area_fraction == pytest.approx(2 / math.pi * math.asin(math.sqrt(ratio)), abs=1.5 / 256)
        assert step.max_pressure == pytest.approx(2 * math.sqrt(ratio) * full, rel=1e-4)
        assert step.mean_gap == pytest.approx(amplitude * (1 - ratio * (1 - math.log(ratio))), abs=2e-4 * amplitude)
        assert step.residual <= 1e-10 and step.solves == 1 and step.clusters == 1
    pressure = solver.pressure_field()
    assert pressure.shape == (4, 256) and pressure.dtype == np.float64
    assert pressure.mean() == pytest.approx(0.5 * full, rel=1e-12)
    gap = solver.gap_field()
    assert gap.shape == (4, 256) and np.all(gap[pressure > 0] == 0) and np.all(gap >= 0)
    assert gap.mean() == pytest.approx(step.mean_gap, rel=1e-12)


def test_a_real_map_by_pressure_and_by_gap():
    surface = topography.read_height_map(AFM)
    topography.subtract_plane(surface, topography.fit_plane(surface))
    solver = topography.ExactContact(surface, contact_modulus=1e11, boundary="padded", kernel="love")
    step = solver.at_pressure(1e7)
    assert 0 < step.area_fraction < 0.01 and step.stiffness > 0 and step.clusters >= 1
    assert step.separation_from_mean_summit == pytest.approx(step.mean_gap - solver.mean_summit_height)
    again = topography.ExactContact(surface, contact_modulus=1e11, boundary="padded", kernel="love")
    by_gap = again.at_mean_gap(step.mean_gap)
    assert by_gap.pressure == pytest.approx(step.pressure, rel=1e-5) and by_gap.solves > 1


def test_the_solvers_agree_on_a_real_map():
    surface = topography.read_height_map(AFM)
    topography.subtract_plane(surface, topography.fit_plane(surface))
    reference = topography.ExactContact(surface, contact_modulus=1e11, solver="polonsky-keer", coarse_start=False)
    fast = topography.ExactContact(surface, contact_modulus=1e11)
    r, f = reference.at_pressure(1e7), fast.at_pressure(1e7)
    assert r.coarse_iterations == 0 and f.coarse_iterations > 0
    assert f.iterations < r.iterations and f.stiffness_iterations < r.stiffness_iterations
    assert f.contact_points == r.contact_points
    assert f.mean_gap == pytest.approx(r.mean_gap, rel=1e-7)
    assert f.stiffness == pytest.approx(r.stiffness, rel=1e-6)


def test_errors():
    surface = wavy(32)
    with pytest.raises(asperity.Error):
        topography.ExactContact(surface, contact_modulus=-1)
    with pytest.raises(ValueError):
        topography.ExactContact(surface, contact_modulus=1e11, boundary="open")
    with pytest.raises(ValueError):
        topography.ExactContact(surface, contact_modulus=1e11, kernel="hertz")
    with pytest.raises(ValueError):
        topography.ExactContact(surface, contact_modulus=1e11, solver="multigrid")
    solver = topography.ExactContact(surface, contact_modulus=1e11, max_iterations=1)
    with pytest.raises(asperity.Error, match="did not converge"):
        solver.at_pressure(1e8)
    with pytest.raises(asperity.Error):
        solver.at_mean_gap(-1e-9)


def test_persson_theory_of_a_map():
    surface = topography.self_affine_surface(128, 128, 1e-7, 1e-7, hurst=0.8, rms_height=1e-8, seed=5)
    spectrum = topography.radial_power_spectrum(surface, edges="none")
    assert spectrum.edges_treatment == "none" and spectrum.edges.size == spectrum.density.size + 1
    assert spectrum.variance == pytest.approx(spectrum.map_variance, rel=1e-9)
    # the spectrum against numpy's periodogram: the same power over the annuli
    h = surface.heights - surface.heights.mean()
    power = np.abs(np.fft.fft2(h)) ** 2 / h.size ** 2
    qx = 2 * math.pi * np.fft.fftfreq(128, 1e-7)
    q = np.hypot(qx[None, :], qx[:, None])
    inside = (q >= spectrum.edges[0]) & (q < spectrum.edges[-1])
    area = math.pi * (spectrum.edges[1:] ** 2 - spectrum.edges[:-1] ** 2)
    assert (spectrum.density * area).sum() == pytest.approx(power[inside].sum(), rel=1e-9)
    persson = topography.PerssonContact(spectrum, contact_modulus=1e11)
    assert persson.gamma == 0.42
    low, high = persson.at_pressure(1e5), persson.at_pressure(1e7)
    assert 0 < low.area_fraction < high.area_fraction < 1 and low.mean_gap > high.mean_gap > 0
    assert high.stiffness_per_area > low.stiffness_per_area > 0
    assert math.isnan(persson.at_pressure(-1).mean_gap)
    with pytest.raises(ValueError):
        topography.radial_power_spectrum(surface, edges="blackman")
    with pytest.raises(asperity.Error):
        topography.PerssonContact(spectrum, contact_modulus=0)


def test_the_exact_contact_in_the_surface_analysis():
    surface = topography.self_affine_surface(64, 64, 1e-7, 1e-7, hurst=0.8, rms_height=1e-8, seed=2)
    contact = topography.ContactOptions(1e11, pressures=[1e6, 1e7], curve_points=5, exact=True, exact_points=3,
                                        exact_boundary="periodic", exact_kernel="fourier")
    assert contact.exact and contact.exact_boundary == "periodic" and contact.persson
    analysis = topography.analyse_height_map(surface, assessment=topography.AssessmentOptions(bootstrap=0), contact=contact)
    comparison = analysis.contact
    labels = [m.label for m in comparison.models]
    assert labels[-2:] == ["persson", "exact"]
    exact = comparison.find("exact")
    assert exact.served and "boundary elements" in comparison.exact_method
    assert exact.at_pressures.pressure.tolist() == [1e6, 1e7]
    for m in comparison.models:
        if m.served and m.label != "exact":
            assert m.stiffness_over_exact.size == 2 and m.area_over_exact.size == 2
            assert np.allclose(m.stiffness_over_exact, m.at_pressures.stiffness / exact.at_pressures.stiffness,
                               equal_nan=True)
    assert comparison.closest_to_exact in labels and comparison.exact_headline.startswith("Against the exact")
    with pytest.raises(ValueError):
        contact.exact_kernel = "hertz"


def test_self_affine_surface():
    surface = topography.self_affine_surface(64, 32, 1e-6, 1e-6, hurst=0.7, rms_height=2e-7, seed=3)
    assert surface.heights.shape == (32, 64)
    assert surface.heights.std() == pytest.approx(2e-7, rel=1e-12) and abs(surface.heights.mean()) < 1e-20
    # the spectral gradient against numpy's FFT
    h = surface.heights
    qx = 2 * math.pi * np.fft.fftfreq(64, 1e-6)
    qy = 2 * math.pi * np.fft.fftfreq(32, 1e-6)
    q2 = qx[None, :] ** 2 + qy[:, None] ** 2
    expected = math.sqrt((q2 * np.abs(np.fft.fft2(h)) ** 2).sum()) / h.size
    assert topography.spectral_rms_gradient(surface) == pytest.approx(expected, rel=1e-12)
    with pytest.raises(asperity.Error):
        topography.self_affine_surface(64, 64, 1e-6, 1e-6, hurst=1.5)


def test_one_solver_shared_by_threads():
    surface = topography.self_affine_surface(64, 64, 1e-6, 1e-6, seed=5)
    solver = topography.ExactContact(surface, contact_modulus=1e11, threads=1)
    reference = topography.ExactContact(surface, contact_modulus=1e11, threads=1).at_pressure(1e8)
    results, errors = [], []

    def work():
        try:
            for _ in range(3):
                results.append(solver.at_pressure(1e8).contact_points)
        except Exception as error:  # noqa: BLE001 - reported below
            errors.append(error)

    threads = [threading.Thread(target=work) for _ in range(3)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert not errors and len(results) == 9
    # each from a different warm start: the same contact to within a few points
    assert all(abs(r - reference.contact_points) <= 3 for r in results)


# ---- inputs answered or refused before any iteration, memory refused up front (issue 37) ----

def test_full_contact_answered_in_closed_form():
    modulus, wavelength, amplitude = 1e11, 1e-3, 1e-6
    solver = topography.ExactContact(wavy(128), contact_modulus=modulus)
    assert solver.full_contact_pressure == pytest.approx(math.pi * modulus * amplitude / wavelength, rel=1e-12)
    step = solver.at_pressure(1e30)  # was 20,000 iterations and "did not converge"
    assert step.area_fraction == 1 and step.iterations == 0 and math.isinf(step.stiffness)
    padded = topography.ExactContact(wavy(128), contact_modulus=modulus, boundary="padded")
    assert math.isinf(padded.full_contact_pressure)


def test_hopeless_pressures_refused_with_the_bound():
    solver = topography.ExactContact(wavy(64), contact_modulus=1e-3, boundary="padded")
    with pytest.raises(asperity.Error, match=r"p/E\* 1e\+09\) is beyond the solver's numerical range.*at most"):
        solver.at_pressure(1e6)
    with pytest.raises(asperity.Error, match="below one node of contact.*ask for at least"):
        solver.at_pressure(1e-300)


def test_hardness_caps_the_pressure():
    # Westergaard's wavy surface at half its full-contact pressure: the elastic peak is above the
    # mean contact pressure, so a hardness between them makes the crests plastic
    modulus, wavelength, amplitude = 1e11, 1e-3, 1e-6
    full = math.pi * modulus * amplitude / wavelength
    elastic = topography.ExactContact(wavy(128), contact_modulus=modulus).at_pressure(0.5 * full)
    assert elastic.plastic_points == 0 and elastic.plastic_area_fraction == 0
    hardness = 0.9 * elastic.max_pressure
    solver = topography.ExactContact(wavy(128), contact_modulus=modulus, hardness=hardness)
    step = solver.at_pressure(0.5 * full)
    assert step.plastic_points > 0 and step.max_pressure == hardness
    assert step.plastic_area_fraction == step.plastic_points / (128 * 4)
    assert np.max(solver.pressure_field()) == hardness
    assert solver.plastic_limit == hardness
    with pytest.raises(asperity.Error, match="every point plastic carries"):
        solver.at_pressure(hardness)


def test_adhesion_loading_and_unloading():
    # Westergaard's wavy surface with a Maugis-Dugdale zone: approached by mean gap down then up,
    # the unloading carries tension where the loading, at the same gap, carried less (hysteresis)
    modulus, wavelength, amplitude = 1e9, 1e-3, 1e-6
    work, stress = 2.0, 1e7   # range 0.2 um; Johnson's (1995) alpha = (2 w L / (pi^2 E* g^2))^1/2 = 0.64
    solver = topography.ExactContact(wavy(64), contact_modulus=modulus, work_of_adhesion=work, adhesive_stress=stress)
    gaps = [3e-6, 2e-6, 1.2e-6, 0.8e-6]
    loading = [solver.at_mean_gap(g) for g in gaps]
    unloading = [solver.at_mean_gap(g) for g in reversed(gaps)]
    assert loading[0].adhesive_points == 0 and loading[0].pressure == 0
    assert all(s.adhesive_points >= s.contact_points for s in loading + unloading)
    for s in loading + unloading:
        assert s.load == pytest.approx(s.pressure * solver.nominal_area)
        assert s.adhesive_pressure == pytest.approx(stress * s.adhesive_points / (64 * 4))
    # at each gap at least the loading's tension on unloading, and more at some
    differences = [u.pressure - l.pressure for u, l in zip(reversed(unloading), loading)]
    assert max(differences) <= 1e-9 * stress and min(differences) < -0.05 * stress
    assert loading[1].contact_points == 0 and unloading[-2].contact_points > 0  # at 2e-6 m: the contact kept
    with pytest.raises(asperity.Error, match="adhesive contact is solved at the flat's positions"):
        solver.at_pressure(1e5)
    fresh = topography.ExactContact(wavy(64), contact_modulus=modulus, work_of_adhesion=work, adhesive_stress=stress)
    step = fresh.at_approach(0.8e-6)
    assert step.approach == 0.8e-6 and step.adhesive_points >= step.contact_points > 0
    field = fresh.pressure_field()  # the net pressure: tension at the contact's edge, at most the adhesive stress
    assert -stress <= np.min(field) < -0.5 * stress and step.max_pressure == pytest.approx(np.max(field))


def test_max_memory_refused_before_allocating():
    with pytest.raises(asperity.Error, match=r"\(64 x 64 points, padded to a 128 x 128 solve grid\) needs about "
                                             r"[0-9.]+ MB, more than the 1 MB allowed"):
        square = topography.HeightMap(np.tile(1e-6 * np.sin(np.arange(64) / 5), (64, 1)), 1e-6, 1e-6)
        topography.ExactContact(square, contact_modulus=1e11, boundary="padded", max_memory=1_000_000)
    solver = topography.ExactContact(wavy(64), contact_modulus=1e11, max_memory=10_000_000)
    assert 0 < solver.memory_estimate <= 10_000_000


def test_write_table_checks_every_limit_before_the_first_solve(tmp_path):
    solver = topography.ExactContact(wavy(64), contact_modulus=1e11, boundary="padded")
    with pytest.raises(asperity.Error, match="description would hold 60001 bytes"):
        solver.write_table(tmp_path / "t.h5", [1e4, 1e5, 1e6], description="x" * 60001)
    with pytest.raises(asperity.Error, match="below one node of contact"):
        solver.write_table(tmp_path / "t.h5", [1e-300, 1e5, 1e6])
    assert not (tmp_path / "t.h5").exists()


def test_write_table_checks_cap(tmp_path):
    """max_checks=5: the two estimates only (2 and 5 checks an interval); below 5 refused."""
    surface = topography.HeightMap(np.sin(np.arange(32.0)[None, :] * 0.4) * np.cos(np.arange(32.0)[:, None] * 0.3) * 1e-7,
                                   1e-6, 1e-6)
    solver = topography.ExactContact(surface, contact_modulus=1e11)
    nodes = solver.write_table(tmp_path / "five.h5", [1e5, 1e6, 1e7], max_checks=5)
    curves = asperity.ContactCurves(tmp_path / "five.h5")
    assert len(nodes) == 3 and curves.check_points == 10 and curves.bound_method == "checks-until-settled"
    with pytest.raises(asperity.Error, match="at least 5 checks each"):
        solver.write_table(tmp_path / "four.h5", [1e5, 1e6, 1e7], max_checks=4)
    assert not (tmp_path / "four.h5").exists()


def test_outputs_follow_the_output_policy(tmp_path):
    """A file not asperity's is kept unless overwrite=True; a planted link is never followed (issue 37)."""
    surface = topography.HeightMap(np.sin(np.arange(32.0)[None, :] * 0.4) * np.cos(np.arange(32.0)[:, None] * 0.3) * 1e-7,
                                   1e-6, 1e-6)
    mine = tmp_path / "mine.h5"
    mine.write_text("my own notes\n")
    victim = tmp_path / "victim"
    victim.write_text("the victim\n")
    (tmp_path / "link.gsf").symlink_to(victim)
    with pytest.raises(asperity.Error, match="not a Gwyddion simple field"):
        topography.write_gsf(surface, mine)
    assert mine.read_text() == "my own notes\n"
    with pytest.raises(asperity.Error, match="symbolic link"):
        topography.write_gsf(surface, tmp_path / "link.gsf")
    assert victim.read_text() == "the victim\n"
    topography.write_gsf(surface, tmp_path / "map.gsf")
    topography.write_gsf(surface, tmp_path / "map.gsf")  # its own kind: replaced
    solver = topography.ExactContact(surface, contact_modulus=1e11)
    with pytest.raises(asperity.Error, match="not a contact-curves table"):
        solver.write_table(mine, [1e5, 1e6, 1e7])
    assert mine.read_text() == "my own notes\n"
    solver.write_table(mine, [1e5, 1e6, 1e7], overwrite=True)
    curves = asperity.ContactCurves(mine)
    with pytest.raises(asperity.Error, match="not a contact-curves table"):
        curves.write(tmp_path / "map.gsf")
    curves.write(tmp_path / "copy.h5")
    curves.write(tmp_path / "copy.h5")
