"""asperity: Greenwood-Williamson asperity integrals from precomputed tables.

The integrals X_n(s) -- J_n on the tail side, K_n on the bounded side, the Greenwood-Tripp F_n
for the Gaussian -- for n = twice_order/2 in 0, 1/2, 1, 3/2, 2, 5/2, served in nanoseconds to
about 1e-12, and the physical contact built on them (docs/model.md has the conventions).

    import asperity, numpy as np
    table = asperity.Table.open_default()            # or asperity.Table.open("file.h5")
    curve = table.curve("weibull", "bounded", 1.73)  # distribution, side, shape
    load = curve.value(3, np.linspace(-1.0, -0.01, 100))   # X_3/2: an ndarray

Measured surfaces -- reading height maps, statistics, summits, fitted height distributions with
their evidence and the contact curves of each fit -- are in the submodule asperity.topography
(docs/surfaces.md):

    from asperity import topography
    analysis = topography.analyse_surface_file("surface.x3p", contact=topography.ContactOptions(1e11))
    analysis.to_dict()["fits"]["summit_heights"]["verdict"]

Many files -- a production line's parts -- go through asperity.batch on a Dask cluster into one
table and each surface's JSON, resuming after an interruption (needs python3-distributed):

    from asperity import batch
    if __name__ == "__main__":  # in a script: its worker processes import it again
        rows = batch.analyse_files(paths, "results", contact_modulus=1.1e11)   # results/surfaces.csv

The common figures -- separation, real area and stiffness against load, one model or several
compared -- are drawn by asperity.plot (matplotlib, imported only when it draws):

    figure, axes = asperity.plot.contact_figure({"Gaussian": model1, "Weibull a = 1.6": model2})

Orders are twice_order (0..5) or the quantity's name: curve.value("load", s) is curve.value(3, s).
Arrays of any shape go through the library's vectorized batch path (no Python loop; the GIL
is released for large arrays); numbers give floats. Errors raise asperity.Error with the
library's message; a ContactModel past Greenwood-Williamson's validity (real area above
gw_area_fraction_limit of the nominal area) warns with asperity.AreaFractionWarning; a query
outside the range a table serves (a scene table's, contact curves') is NaN with an
asperity.OutOfRangeWarning naming the range. The names
mirror the C++ API (include/asperity/*.hpp). Two surface types: RoughSurface (formerly
PhysicalSurface) is a physical surface in SI units for ContactModel; SurfaceScales (formerly
Surface) is the four scales N, R, sigma_s, E* the lower-level contact_at multiplies a curve by.
"""
import sys as _sys

from ._asperity import (  # noqa: F401
    ALL_ORDERS,
    ORDER_COUNT,
    AreaFractionWarning,
    ContactCurves,
    ContactCurvesState,
    ContactModel,
    ContactState,
    Curve,
    CurveOptions,
    CurveSet,
    Distribution,
    Error,
    ImplausibleValueWarning,
    InstructionSet,
    InverseCurve,
    OutOfRangeWarning,
    PerssonLaw,
    PhysicalState,
    PhysicalSurface,
    RoughSurface,
    Scene,
    SceneCurve,
    SceneCurveView,
    Side,
    Surface,
    SurfaceScales,
    Table,
    __version__,
    bandwidth_alpha,
    best_instruction_set,
    contact_at,
    contact_modulus_from,
    contact_modulus_given,
    gaussian_log_density,
    gaussian_surface_from_moments,
    gw_area_fraction_limit,
    height_scale_from_rms,
    implausible_values,
    law_curves,
    law_curves_keywords,
    nominal_pressure_from_load,
    order_of,
    origin_from_standardized,
    parse_scene,
    quantity_twice_order,
    read_scene_file,
    separation_at_load,
    serve_scene,
    standardized_from_origin,
    tabulate_law_scene,
    tabulated_pressure_overclosure_card,
    weibull_log_density,
    weibull_mean,
    weibull_moment,
    weibull_rms,
)
from ._asperity import topography  # noqa: F401

# `import asperity.topography` and `from asperity.topography import ...`: the submodule lives in
# the extension, so it is registered under its package name.
_sys.modules[__name__ + ".topography"] = topography

from . import batch  # noqa: E402,F401 (pure Python; imports dask only when it runs)
from . import plot  # noqa: E402,F401 (pure Python; imports matplotlib only when it draws)

__all__ = [
    "ImplausibleValueWarning", "implausible_values",
    "ALL_ORDERS", "ORDER_COUNT", "AreaFractionWarning", "ContactCurves", "ContactCurvesState", "ContactModel", "ContactState", "Curve", "CurveOptions", "CurveSet",
    "Distribution", "Error", "InstructionSet", "InverseCurve", "OutOfRangeWarning", "PerssonLaw", "PhysicalState",
    "PhysicalSurface", "RoughSurface", "Scene", "SceneCurve", "SceneCurveView", "Side", "Surface", "SurfaceScales", "Table", "bandwidth_alpha",
    "batch", "best_instruction_set", "contact_at", "contact_modulus_from", "contact_modulus_given", "gaussian_log_density",
    "gaussian_surface_from_moments", "gw_area_fraction_limit", "height_scale_from_rms", "law_curves", "law_curves_keywords", "nominal_pressure_from_load", "order_of", "origin_from_standardized",
    "parse_scene", "plot", "quantity_twice_order", "read_scene_file", "separation_at_load", "serve_scene",
    "standardized_from_origin", "tabulate_law_scene", "tabulated_pressure_overclosure_card", "topography", "weibull_log_density", "weibull_mean", "weibull_moment",
    "weibull_rms",
]

