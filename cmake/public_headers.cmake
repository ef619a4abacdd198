# The public face: the headers each component installs, listed one by one (cmake/install.cmake).
# Nothing else is installed: the runtime's internals (runtime/include/asperity/detail/, among
# them the table format's segment kinds and maps, segment_kind.hpp and segment_map.hpp) and each
# folder's private headers stay in the source tree. tests/check_layering.cmake checks that every
# header under include/ is listed here once and that a listed header includes only listed ones.
set(ASPERITY_RUNTIME_HEADERS
  asperity.h             # the C API (Fortran: asperity.f90, the fortran component)
  error.hpp              # asperity::Error, the one exception type
  integrals.hpp          # distributions, sides, orders: which integral
  model.hpp              # integrals.hpp's former name (deprecated)
  layout.hpp             # a curve's knot layout (SegmentKind, SegmentSpec): Curve and CurveSet name it
  instruction_set.hpp
  curve.hpp              # one resolved curve: the hot handle
  asymptotic.hpp         # the series beyond the table
  table_data.hpp         # a table's contents (TableData, CurveSet): generated, written, read
  table.hpp table_file.hpp table_writer.hpp
  contact_curves_data.hpp contact_curves.hpp  # contact curves against separation: a measured surface served
  contact_scales.hpp contact.hpp    # contact_at: the four quantities of a curve
  surface.hpp            # a physical surface, unit conversions and input checks
  inverse.hpp contact_model.hpp persson.hpp
  separation_datum.hpp   # where separations are measured from (origin, mean summit, mean plane)
  plausibility.hpp       # units caught: implausible surface parameters
  record_fields.hpp      # a result record defined once: its fields, struct, CSV columns (the writers made from it)
  physical_state_fields.hpp  # the physical state's fields, once (C, Fortran, Python, CSV made or checked from it)
  law_combination.hpp    # how a law's rough-surface quantities combine the tabulated orders (Hertz's numbers)
  contact_law.hpp        # single-asperity contact laws (Hertz, CEB, ZMC, KE, JG, DMT, JKR, MD)
  contact_law_registry.hpp  # the laws as a registry: parameters, descriptors, typed construction
  scene.hpp scene_curves.hpp
  pressure_overclosure.hpp          # FE export: CalculiX/Abaqus pressure-overclosure cards
  number_text.hpp                   # the one strict number reader and writer
  interrupt.hpp output.hpp)         # stopping long work; the one output policy (every file written)
set(ASPERITY_GENERATOR_HEADERS
  generator/quadrature.hpp generator/chain_ode.hpp generator/generate.hpp generator/scene_table.hpp
  generator/law_curves.hpp)
set(ASPERITY_TOPOGRAPHY_HEADERS
  topography/units.hpp topography/height_map.hpp topography/height_map_io.hpp topography/surface_formats.hpp
  topography/leveling.hpp topography/statistics.hpp topography/summits.hpp topography/distribution_fit.hpp
  topography/goodness_of_fit.hpp topography/synthetic.hpp topography/surrogates.hpp topography/surface_tests.hpp topography/surface_verdict.hpp
  topography/summit_contact.hpp topography/contact_comparison.hpp topography/law_contact.hpp topography/analysis.hpp
  topography/surface_report.hpp topography/next_steps.hpp topography/exact_contact.hpp topography/exact_contact_report.hpp topography/exact_contact_table.hpp topography/self_affine.hpp
  topography/persson_contact.hpp)
set(ASPERITY_FORTRAN_SOURCES asperity.f90)
