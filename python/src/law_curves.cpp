// asperity.law_curves and asperity.tabulate_law_scene: a contact law's rough-surface curves
// tabulated from Python by the generator (asperity/generator/law_curves.hpp), as tablegen does a
// law scene, and served as an asperity.ContactCurves (docs/contact-laws.md section 8).
//
// The keyword arguments are a [[law]] scene's keys (asperity/scene.hpp), the law's parameters the
// contact-law registry's: they become typed inputs checked by make_scene_law, the one check that
// the command line (asperity contact --law) and a scene file go through too.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "interrupt.hpp"
#include "asperity/contact_curves.hpp"
#include "asperity/contact_law_registry.hpp"
#include "asperity/error.hpp"
#include "asperity/generator/law_curves.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/number_text.hpp"
#include "asperity/scene.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {
namespace {

std::string type_name(const py::handle& value) { return py::str(py::type::of(value).attr("__name__")); }

// A keyword's value: a number (not a bool, a string or a sequence).
double number_of(const std::string& key, const py::handle& value) {
  if (py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value) || !py::hasattr(value, "__float__") ||
      py::isinstance<py::sequence>(value))
    throw Error("law_curves: " + key + " must be a number, not a " + type_name(value));
  return py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
}

std::string text_of(const std::string& key, const py::handle& value) {
  if (!py::isinstance<py::str>(value)) throw Error("law_curves: " + key + " must be a string, not a " + type_name(value));
  return value.cast<std::string>();
}

// The parameters a law takes, as keywords ("yield_strength, poisson")
std::string law_keys_text(ContactLawKind kind) {
  const ContactLawDescriptor& law = *find_contact_law(kind);
  std::string keys;
  for (int k = 0; k < law.parameter_count; ++k)
    keys += std::string(k ? ", " : "") + law_parameter_info(law.parameters[k].parameter).key;
  return keys.empty() ? "none" : keys;
}

// A law parameter's keyword into `in`; false when `key` is not a law parameter's.
bool read_law_parameter(const std::string& key, const py::handle& value, SceneLawInputs& in) {
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p) {
    if (key != p->key) continue;
    if (!p->choices[0]) {
      in.material.set(p->id, number_of(key, value));
      return true;
    }
    const bool whole = py::isinstance<py::int_>(value) && !py::isinstance<py::bool_>(value);
    double index;
    if (!law_choice_index(p->id, whole ? std::string(py::str(value)) : text_of(key, value), index))
      throw Error("law_curves: " + key + " is " + p->range_text);
    in.material.set(p->id, index);
    return true;
  }
  return false;
}

// A [[law]] key of the surface or the range into `in`; false when `key` is none of them.
bool read_scene_key(const std::string& key, const py::handle& value, SceneLawInputs& in) {
  const std::pair<const char*, double*> numbers[] = {
      {"contact_modulus", &in.contact_modulus}, {"shape", &in.shape},
      {"height_scale", &in.height_scale},       {"summit_radius", &in.summit_radius},
      {"summit_density", &in.summit_density},   {"nominal_area", &in.nominal_area},
      {"max_rel_error", &in.max_rel_error},     {"approach_separation", &in.approach_separation}};
  for (const auto& [name, target] : numbers)
    if (key == name) return *target = number_of(key, value), true;
  if (key == "name") {
    in.name = text_of(key, value);
  } else if (key == "distribution") {
    if (!parse_distribution(text_of(key, value), in.distribution))
      throw Error("law_curves: distribution must be 'weibull' or 'gaussian'");
  } else if (key == "side") {
    if (!parse_side(text_of(key, value), in.side)) throw Error("law_curves: side must be 'tail' or 'bounded'");
    in.side_given = true;
  } else if (key == "separation") {
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != 2)
      throw Error("law_curves: separation must be a pair (smin, smax)");
    const py::sequence pair = value.cast<py::sequence>();
    in.range_min = number_of("separation", pair[0]);
    in.range_max = number_of("separation", pair[1]);
  } else {
    return false;
  }
  return true;
}

// A keyword's Python type in the stubs ("float", "str", "pair": (smin, smax)): a [[law]] key's
// (asperity/scene.hpp's scene_law_keys) or a law parameter's (the registry's)
const char* scene_key_type(const std::string& key) {
  if (key == "name" || key == "distribution" || key == "side") return "str";
  return key == "separation" ? "pair" : "float";
}

// Every keyword of law_curves and its type: the [[law]] keys but `law`, then every law's parameters
std::vector<std::pair<std::string, std::string>> law_curves_keywords() {
  std::vector<std::pair<std::string, std::string>> keywords;
  for (const SceneLawKey& k : scene_law_keys)
    if (std::string(k.keyword) != "law") keywords.emplace_back(k.keyword, scene_key_type(k.keyword));
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p)
    keywords.emplace_back(p->key, p->choices[0] ? "str" : "float");
  return keywords;
}

// The surface's and the range's keywords, for messages and the docstring ("contact_modulus, ...")
std::string scene_keywords_text() {
  std::string text;
  for (const SceneLawKey& k : scene_law_keys)
    if (std::string(k.keyword) != "law") text += std::string(text.empty() ? "" : ", ") + k.keyword;
  return text;
}

// The keywords of law_curves as a law scene's typed inputs: each key is a law parameter (the
// registry's) or a [[law]] key (asperity/scene.hpp's scene_law_keys), nothing else.
SceneLawInputs law_inputs(const std::string& law, const py::kwargs& keys) {
  SceneLawInputs in;
  if (!contact_law_kind_of(law.c_str(), in.law))
    throw Error("law_curves: law must be one of " + contact_law_names(", ", true) + ", not '" + quote_text(law) + "'");
  for (const auto& item : keys) {
    const std::string key = py::str(item.first);
    if (!read_law_parameter(key, item.second, in) && !read_scene_key(key, item.second, in))
      throw Error("law_curves: '" + quote_text(key) + "' is not a law scene's key (" + law + "'s: " +
                  law_keys_text(in.law) + "; the surface's and the range's: " + scene_keywords_text() + ")");
  }
  return in;
}

// progress= of law_curves: the callable is given a dict (pass, nodes, checked, intervals,
// evaluations, elapsed [s]) at most once a second, with the GIL taken for it. Its exception ends
// the tabulation and is what the call raises.
struct ProgressCall {
  py::object callable;  // None: no progress
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now(), shown = start;

  void operator()(const generator::LawCurvesProgress& at) {
    const auto now = std::chrono::steady_clock::now();
    if (now - shown < std::chrono::seconds(1)) return;
    shown = now;
    py::gil_scoped_acquire gil;
    try {
      callable(py::dict("pass"_a = at.pass, "nodes"_a = at.nodes, "checked"_a = at.checked,
                        "intervals"_a = at.intervals, "evaluations"_a = at.evaluations,
                        "elapsed"_a = std::chrono::duration<double>(now - start).count()));
    } catch (py::error_already_set& error) {
      error.restore();  // pending again: raised at the call's boundary (interrupt.hpp)
      throw Interrupted();
    }
  }
};

// A law scene tabulated (without the GIL, one thread; Ctrl-C stops it)
ContactCurves tabulate(const SceneLaw& law, const std::string& source, const py::object& progress = py::none()) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be a callable or None, not '" +
                         std::string(py::str(py::type::handle_of(progress).attr("__name__"))) + "'");
  ProgressCall call{progress};
  std::function<void(const generator::LawCurvesProgress&)> report;
  if (!progress.is_none()) report = std::ref(call);
  generator::LawCurvesResult result =
      interruptible([&] { return generator::generate_law_curves(law, source, report); });
  return ContactCurves(std::move(result.data));
}

// The keywords every law parameter has, for the docstring (the registry's)
std::string law_keywords_doc() {
  std::string doc;
  for (const LawParameterInfo* p = law_parameters_begin(); p != law_parameters_end(); ++p)
    doc += std::string("    ") + p->key + ": " + p->meaning + " (" + laws_taking(p->id) + ")\n";
  return doc;
}

}  // namespace

void bind_law_curves(py::module_& m) {
  static const std::string doc =
      "A contact law's rough-surface curves (pressure, stiffness, real area fraction against separation),\n"
      "tabulated now by the generator to max_rel_error with the error measured and stored, as tablegen does a\n"
      "law scene (docs/contact-laws.md section 8), served as an asperity.ContactCurves (write it with .write).\n"
      "law: " + contact_law_names() + ".\n"
      "The keywords are a [[law]] scene's keys (all of them, with their types: law_curves_keywords): " +
      scene_keywords_text() + "\n(separation=(smin, smax): dimensionless, origin convention; max_rel_error: 1e-10 .. 1e-2;\n"
      "approach_separation=s0, an adhesive law's (dmt, jkr, maugis-dugdale): the withdrawal (unloading, fixed grips)\n"
      "branch after an approach to s0 <= smin instead of the approach branch; its pull_off_pressure is the\n"
      "withdrawal's),\n"
      "and the law's parameters:\n" + law_keywords_doc() +
      "Raises asperity.Error naming the keyword for a missing, unknown or bad one, or where the curves cannot\n"
      "be tabulated. It runs without the GIL; Ctrl-C stops it (KeyboardInterrupt). progress=callable: called at\n"
      "most once a second with a dict (pass, nodes, checked, intervals, evaluations, elapsed [s]); its\n"
      "exception stops the tabulation. Example:\n"
      "    asperity.law_curves('kogut-etsion', contact_modulus=1.13e11, yield_strength=1e9, poisson=0.3,\n"
      "                        distribution='gaussian', height_scale=1e-6, summit_radius=1e-4,\n"
      "                        summit_density=4e8, nominal_area=1e-4, separation=(0, 4), max_rel_error=1e-6)";
  py::dict keywords;
  for (const auto& [key, type] : law_curves_keywords()) keywords[py::str(key)] = type;
  m.attr("law_curves_keywords") = keywords;
  m.def(
      "law_curves",
      [](const std::string& law, const py::object& progress, const py::kwargs& keys) {
        const SceneLawInputs in = law_inputs(law, keys);
        SceneLaw scene;
        try {
          scene = make_scene_law(in, LawNaming::keyword);
        } catch (const SceneLawError& error) {
          throw Error(std::string("asperity.law_curves: ") + error.what());
        }
        return tabulate(scene, "asperity.law_curves", progress);
      },
      "law"_a, py::kw_only(), "progress"_a = py::none(), doc.c_str());
  m.def(
      "tabulate_law_scene",
      [](const std::string& text) {
        const Scene scene = parse_scene(text, "asperity.tabulate_law_scene");
        if (scene.laws.size() != 1 || !scene.curves.empty())
          throw Error("asperity.tabulate_law_scene: a law scene needs exactly one [[law]] and no [[curve]]");
        return tabulate(scene.laws.front(), "asperity.tabulate_law_scene");
      },
      "text"_a, "The same from a law scene's TOML text (a scene file's contents: one [[law]], no [[curve]]).");
}

}  // namespace asperity::python
