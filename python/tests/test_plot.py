"""asperity.plot drawn headless (Agg): each figure has one line per model with finite data, its
legend outside the axes (never on a curve), and it is written as PNG and SVG; without matplotlib
the import error says what to install. Run by ctest (python_tests)."""
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

import asperity

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from asperity import plot  # noqa: E402


@pytest.fixture(scope="module")
def models():
    table = asperity.Table.open_default()
    common = dict(summit_radius=1e-4, summit_density=1e10, nominal_area=1e-4, contact_modulus=1.15e11)
    return {
        "Gaussian": asperity.ContactModel(table, asperity.RoughSurface("gaussian", shape=None, rms=5e-7, **common)),
        "Weibull a = 1.6": asperity.ContactModel(table, asperity.RoughSurface("weibull", shape=1.6, rms=5e-7, **common)),
        "Weibull bounded a = 3": asperity.ContactModel(
            table, asperity.RoughSurface("weibull", "bounded", shape=3.0, rms=5e-7, **common)),
    }


def check_axes(ax, count):
    lines = ax.get_lines()
    assert len(lines) == count
    for line in lines:
        x, y = np.asarray(line.get_xdata()), np.asarray(line.get_ydata())
        assert x.size >= 2 and np.all(np.isfinite(x)) and np.all(np.isfinite(y)), line.get_label()
        assert np.all(np.diff(x) > 0)  # swept by load
    assert ax.get_xlabel() == "load [N]" and ax.get_ylabel()


def legend_off_the_data(figure, ax):
    figure.canvas.draw()
    legend = ax.get_legend()
    assert legend is not None
    renderer = figure.canvas.get_renderer()
    box, frame = legend.get_window_extent(renderer), ax.get_window_extent(renderer)
    assert not box.overlaps(frame)  # outside the axes: it cannot cover a curve
    for line in ax.get_lines():       # nor any drawn point
        points = ax.transData.transform(np.column_stack([line.get_xdata(), line.get_ydata()]))
        inside = ((points[:, 0] >= box.x0) & (points[:, 0] <= box.x1) & (points[:, 1] >= box.y0)
                  & (points[:, 1] <= box.y1))
        assert not inside.any(), line.get_label()


def test_each_panel(models, tmp_path):
    for draw in (plot.load_separation, plot.area_load, plot.stiffness_load):
        with warnings.catch_warnings():
            warnings.simplefilter("error", asperity.AreaFractionWarning)  # the default range stays within GW
            ax = draw(models, points=50)
        check_axes(ax, len(models))
        assert [text.get_text() for text in ax.get_legend().get_texts()] == list(models)
        legend_off_the_data(ax.figure, ax)
        for suffix in ("png", "svg"):
            path = tmp_path / f"{draw.__name__}.{suffix}"
            ax.figure.savefig(path)
            assert path.stat().st_size > 5000
        plt.close(ax.figure)


def test_the_physics_in_the_figures(models):
    model = models["Gaussian"]
    ax = plot.area_load(model, points=20)  # one model: labelled by its surface
    x, y = ax.get_lines()[0].get_data()
    assert np.allclose(y, model.at_load(x).area_fraction, rtol=1e-12)
    assert y[0] == pytest.approx(1e-5, rel=1e-6) and y[-1] == pytest.approx(asperity.gw_area_fraction_limit, rel=1e-6)
    assert "Gaussian" in ax.get_legend().get_texts()[0].get_text()
    plt.close(ax.figure)
    ax = plot.load_separation([model], ["G"], load_range=(0.1, 10.0), points=5, separation="origin")
    x, y = ax.get_lines()[0].get_data()
    assert np.allclose(x, np.geomspace(0.1, 10.0, 5)) and np.allclose(y, model.at_load(x).separation * 1e6)
    plt.close(ax.figure)
    figure, given = plt.subplots()
    assert plot.stiffness_load(model, ax=given) is given  # into the caller's axes
    plt.close(figure)


def test_comparing_distributions(models, tmp_path):
    figure, axes = plot.contact_figure(models, points=40)
    assert len(axes) == 3
    for ax in axes:
        check_axes(ax, len(models))
    assert axes[0].get_legend() is None and axes[1].get_legend() is None  # one legend, beside the last
    legend_off_the_data(figure, axes[2])
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    box = axes[2].get_legend().get_window_extent(renderer)
    assert not any(box.overlaps(ax.get_window_extent(renderer)) for ax in axes)
    figure.savefig(tmp_path / "contact.svg")
    figure.savefig(tmp_path / "contact.png")
    assert (tmp_path / "contact.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert b"<svg" in (tmp_path / "contact.svg").read_bytes()[:2000]
    plt.close(figure)


def test_bad_arguments(models):
    model = models["Gaussian"]
    with pytest.raises(ValueError, match="load_range"):
        plot.area_load(model, load_range=(10.0, 1.0))
    with pytest.raises(ValueError, match="2 labels for 1 models"):
        plot.area_load([model], ["a", "b"])
    with pytest.raises(TypeError, match="a ContactModel is needed"):
        plot.area_load([model.surface])
    with pytest.raises(ValueError, match="separation must be 'mean' or 'origin'"):
        plot.load_separation(model, separation="datum")
    with pytest.raises(ValueError, match="points"):
        plot.stiffness_load(model, points=1)
    plt.close("all")


def test_without_matplotlib_the_error_says_what_to_install():
    code = ("import sys; sys.modules['matplotlib'] = None; sys.modules['matplotlib.pyplot'] = None\n"
            "import asperity, asperity.plot\n"   # importing needs no matplotlib
            "t = asperity.Table.open_default()\n"
            "m = asperity.ContactModel(t, asperity.RoughSurface('gaussian', rms=5e-7, summit_radius=1e-4,\n"
            "    summit_density=1e10, nominal_area=1e-4, contact_modulus=1e11))\n"
            "try:\n    asperity.plot.area_load(m)\nexcept ImportError as e:\n    print('ImportError:', e)\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=dict(os.environ))
    assert result.returncode == 0, result.stderr
    assert "ImportError: asperity.plot draws with matplotlib" in result.stdout
    assert "python3-matplotlib" in result.stdout
