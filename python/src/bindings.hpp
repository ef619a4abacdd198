// The parts of the Python module, one binding file each (py_*.cpp, law_curves.cpp, output.cpp),
// registered in this order by module.cpp: a class is bound before any function whose signature
// or default argument names it (pybind11 names a type in a signature when the function is made).
#pragma once
#include <pybind11/pybind11.h>

namespace asperity::python {

// ---- asperity (the runtime library) ----
// asperity.Error, AreaFractionWarning, OutOfRangeWarning, gw_area_fraction_limit (py_errors.cpp)
void bind_errors(pybind11::module_& m);
// asperity.ContactState and asperity.PhysicalState, the answers' records (py_records.cpp)
void bind_records(pybind11::module_& m);
// Distribution, Side, InstructionSet, order_of and the unit densities (py_vocabulary.cpp)
void bind_vocabulary(pybind11::module_& m);
// Curve, CurveOptions (py_curve.cpp)
void bind_curve(pybind11::module_& m);
// CurveSet, Table (py_table.cpp)
void bind_table(pybind11::module_& m);
// SurfaceScales, contact_at and the separation conventions (py_contact.cpp)
void bind_contact(pybind11::module_& m);
// RoughSurface and its unit helpers (py_surface.cpp)
void bind_surface(pybind11::module_& m);
// tabulated_pressure_overclosure_card (py_fe_export.cpp)
void bind_fe_export(pybind11::module_& m);
// InverseCurve (py_inverse.cpp)
void bind_inverse(pybind11::module_& m);
// ImplausibleValueWarning, implausible_values, ContactModel (py_contact_model.cpp)
void bind_contact_model(pybind11::module_& m);
// ContactCurves (py_contact_curves.cpp)
void bind_contact_curves(pybind11::module_& m);
// PerssonLaw (py_persson.cpp)
void bind_persson(pybind11::module_& m);
// scenes: SceneCurve, Scene, SceneCurveView, their readers and serve_scene (py_scene.cpp)
void bind_scene(pybind11::module_& m);
// asperity.law_curves, asperity.tabulate_law_scene (law_curves.cpp): needs asperity.ContactCurves bound
void bind_law_curves(pybind11::module_& m);
// asperity._output: the output policy for the pure-Python parts (output.cpp)
void bind_output(pybind11::module_& m);

// ---- asperity.topography (measured surfaces); m is the submodule ----
// HeightMap, HeightMapFormat, ReadOptions, the readers and write_gsf, units (py_height_map.cpp)
void bind_height_map(pybind11::module_& m);
// leveling, statistics, spectral moments, correlation lengths; summits (py_statistics.cpp)
void bind_statistics(pybind11::module_& m);
void bind_summits(pybind11::module_& m);
// the height models and their fits; the bootstrap's assessment and verdict (py_verdict.cpp)
void bind_fits(pybind11::module_& m);
void bind_assessment(pybind11::module_& m);
// synthetic surfaces (py_synthetic.cpp)
void bind_synthetic(pybind11::module_& m);
// self-affine surfaces, ContactStep, ExactContact (py_exact_contact.cpp)
void bind_exact_contact(pybind11::module_& m);
// Persson's theory of a map; the contact curves of the fits (py_surface_contact.cpp)
void bind_persson_contact(pybind11::module_& m);
void bind_contact_comparison(pybind11::module_& m);
// AnalysisOptions and its parts; the analysis and its report (py_report.cpp)
void bind_analysis_options(pybind11::module_& m);
void bind_report(pybind11::module_& m);

}  // namespace asperity::python
