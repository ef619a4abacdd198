"""The common contact figures of one or more ContactModels, drawn with matplotlib (imported only
when a figure is drawn; Debian: python3-matplotlib):

    import asperity, asperity.plot
    table = asperity.Table.open_default()
    common = dict(rms=5e-7, summit_radius=1e-4, summit_density=1e10, nominal_area=1e-4, contact_modulus=1e11)
    gaussian = asperity.ContactModel(table, asperity.RoughSurface("gaussian", **common))
    weibull = asperity.ContactModel(table, asperity.RoughSurface("weibull", shape=1.6, **common))
    figure, axes = asperity.plot.contact_figure({"Gaussian": gaussian, "Weibull a = 1.6": weibull})
    figure.savefig("contact.svg")

load_separation, area_load and stiffness_load draw one panel each (into `ax`, or a new figure) and
return the Axes; contact_figure draws the three side by side and returns (figure, axes). Each model
is swept by load over `load_range` [N]; by default from a real-area fraction of 1e-5 up to
gw_area_fraction_limit (0.1), where Greenwood-Williamson holds (beyond it the models warn:
asperity.AreaFractionWarning). Legends sit outside the axes, never on the curves.
"""
import math

from ._asperity import gw_area_fraction_limit

__all__ = ["area_load", "contact_figure", "load_separation", "stiffness_load"]

_FRACTION_FROM = 1e-5  # the default sweep's smallest real-area fraction


def _pyplot():
    try:
        import matplotlib.pyplot as pyplot
    except ImportError as error:
        raise ImportError("asperity.plot draws with matplotlib, which this Python cannot import "
                          "(Debian: apt-get install python3-matplotlib; elsewhere: pip install matplotlib): "
                          f"{error}") from error
    return pyplot


def _labelled(models, labels):
    """[(label, model)] from a model, a sequence of models or a {label: model} mapping."""
    if hasattr(models, "at_load"):
        models = [models]
    if hasattr(models, "items"):
        if labels is not None:
            raise TypeError("labels: give them as the mapping's keys or as labels=, not both")
        pairs = [(str(label), model) for label, model in models.items()]
    else:
        models = list(models)
        for model in models:
            if not hasattr(model, "at_load"):
                raise TypeError(f"a ContactModel is needed, not {type(model).__name__!r}")
        if labels is None:
            labels = [_describe(model) for model in models]
        labels = list(labels)
        if len(labels) != len(models):
            raise ValueError(f"{len(labels)} labels for {len(models)} models")
        pairs = list(zip((str(label) for label in labels), models))
    if not pairs:
        raise ValueError("no model to draw")
    for label, model in pairs:
        if not hasattr(model, "at_load"):
            raise TypeError(f"{label!r}: a ContactModel is needed, not {type(model).__name__!r}")
    return pairs


def _describe(model):
    surface = model.surface
    if surface.distribution.name == "gaussian":
        return f"Gaussian, rms {surface.rms:.3g} m"
    return f"Weibull {surface.side.name} a = {surface.shape:.3g}, rms {surface.rms:.3g} m"


def _loads(model, load_range, points):
    import numpy as np

    if int(points) < 2:
        raise ValueError(f"points must be at least 2, not {points}")
    if load_range is None:
        area = model.surface.nominal_area
        low, high = model.at_real_area([_FRACTION_FROM * area, gw_area_fraction_limit * area]).load
    else:
        low, high = (float(value) for value in load_range)
        if not (0 < low < high and math.isfinite(high)):
            raise ValueError(f"load_range must be two loads 0 < low < high [N], not {load_range!r}")
    return np.geomspace(low, high, int(points))


def _states(pairs, load_range, points):
    return [(label, model.at_load(_loads(model, load_range, points))) for label, model in pairs]


def _axes(ax):
    if ax is not None:
        return ax
    _, ax = _pyplot().subplots(layout="constrained")
    return ax


def _legend(ax):
    # outside the axes, to their right: it never covers a curve
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, fontsize="small")


_SEPARATIONS = {"mean": ("mean_separation", "from the mean summit height"),
                "origin": ("separation", "from the origin (docs/model.md)")}


def _separation_field(separation):
    if separation not in _SEPARATIONS:
        raise ValueError(f"separation must be 'mean' or 'origin', not {separation!r}")
    return _SEPARATIONS[separation]


def _load_separation(ax, states, separation):
    field, what = _separation_field(separation)
    for label, state in states:
        ax.plot(state.load, getattr(state, field) * 1e6, label=label)
    ax.set_xscale("log")
    ax.set_xlabel("load [N]")
    ax.set_ylabel(f"separation {what} [µm]")


def _area_load(ax, states):
    for label, state in states:
        ax.plot(state.load, state.area_fraction, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("load [N]")
    ax.set_ylabel("real area / nominal area")


def _stiffness_load(ax, states):
    for label, state in states:
        ax.plot(state.load, state.stiffness, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("load [N]")
    ax.set_ylabel("normal stiffness [N/m]")


def load_separation(models, labels=None, *, load_range=None, points=200, separation="mean", ax=None):
    """The separation [µm] against the load [N] (log), one line per model. separation: 'mean' (from
    the mean summit height, comparable across distributions) or 'origin'. Returns the Axes."""
    _separation_field(separation)
    ax = _axes(ax)
    _load_separation(ax, _states(_labelled(models, labels), load_range, points), separation)
    _legend(ax)
    return ax


def area_load(models, labels=None, *, load_range=None, points=200, ax=None):
    """The real-area fraction A/A0 against the load [N], both log, one line per model. Returns the Axes."""
    ax = _axes(ax)
    _area_load(ax, _states(_labelled(models, labels), load_range, points))
    _legend(ax)
    return ax


def stiffness_load(models, labels=None, *, load_range=None, points=200, ax=None):
    """The normal stiffness [N/m] against the load [N], both log, one line per model. Returns the Axes."""
    ax = _axes(ax)
    _stiffness_load(ax, _states(_labelled(models, labels), load_range, points))
    _legend(ax)
    return ax


def contact_figure(models, labels=None, *, load_range=None, points=200, separation="mean"):
    """The three panels side by side (separation, area fraction and stiffness against load) for one
    model or several compared, one legend for all beside them. Returns (figure, [three Axes])."""
    _separation_field(separation)
    states = _states(_labelled(models, labels), load_range, points)
    figure, axes = _pyplot().subplots(1, 3, figsize=(13.0, 4.0), layout="constrained")
    _load_separation(axes[0], states, separation)
    _area_load(axes[1], states)
    _stiffness_load(axes[2], states)
    _legend(axes[2])
    return figure, list(axes)
