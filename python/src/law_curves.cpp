// asperity.law_curves and asperity.tabulate_law_scene: a contact law's rough-surface curves
// tabulated from Python by the generator (asperity/generator/law_curves.hpp), as tablegen does a
// law scene, and served as an asperity.ContactCurves (docs/contact-laws.md section 8).
//
// The keyword arguments are a [[law]] scene's keys (asperity/scene.hpp): they are written as the
// scene's TOML text and go through the scene's own checks, so that Python, the command line
// (asperity contact --law) and a scene file refuse the same inputs with the same messages.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <functional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "interrupt.hpp"
#include "asperity/contact_curves.hpp"
#include "asperity/error.hpp"
#include "asperity/generator/law_curves.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/number_text.hpp"
#include "asperity/scene.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {
namespace {

// A value as TOML: a number in its shortest exact form, a string quoted (the scene refuses
// control characters; quotes and backslashes are escaped here), a pair of numbers an array.
std::string toml_value(const std::string& key, const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) throw Error("law_curves: " + key + " must be a number or a string, not a bool");
  if (py::isinstance<py::str>(value)) {
    std::string quoted = "\"";
    for (char c : value.cast<std::string>()) {
      if (c == '"' || c == '\\') quoted += '\\';
      quoted += c;
    }
    return quoted + "\"";
  }
  if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value) || py::hasattr(value, "__float__")) {
    if (py::isinstance<py::sequence>(value)) throw Error("law_curves: " + key + " must be a number");
    return format_double(py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>());
  }
  if (py::isinstance<py::sequence>(value)) {
    const py::sequence items = value.cast<py::sequence>();
    std::string array = "[";
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (i) array += ", ";
      const py::handle item = items[i];
      if (py::isinstance<py::bool_>(item) || py::isinstance<py::str>(item) || !py::hasattr(item, "__float__"))
        throw Error("law_curves: " + key + " must be numbers");
      array += format_double(py::float_(py::reinterpret_borrow<py::object>(item)).cast<double>());
    }
    return array + "]";
  }
  throw Error("law_curves: " + key + " has a value of type " + std::string(py::str(py::type::of(value).attr("__name__"))) +
              " (a number, a string or a pair of numbers is wanted)");
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

// The one law of a scene's text, tabulated (without the GIL, one thread; Ctrl-C stops it)
ContactCurves tabulate(const std::string& text, const std::string& source, const py::object& progress = py::none()) {
  const Scene scene = parse_scene(text, source);
  if (scene.laws.size() != 1 || !scene.curves.empty())
    throw Error(source + ": a law scene needs exactly one [[law]] and no [[curve]]");
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be a callable or None, not '" +
                         std::string(py::str(py::type::handle_of(progress).attr("__name__"))) + "'");
  ProgressCall call{progress};
  std::function<void(const generator::LawCurvesProgress&)> report;
  if (!progress.is_none()) report = std::ref(call);
  generator::LawCurvesResult result =
      interruptible([&] { return generator::generate_law_curves(scene.laws.front(), source, report); });
  return ContactCurves(std::move(result.data));
}

}  // namespace

void bind_law_curves(py::module_& m) {
  m.def(
      "law_curves",
      [](const std::string& law, const py::kwargs& keys) {
        // a key name is the scene's; its text is checked there (an unknown key is refused by name)
        std::string text = "[[law]]\nlaw = " + toml_value("law", py::str(law)) + "\n";
        py::object progress = py::none();
        for (const auto& item : keys) {
          const std::string key = py::str(item.first);
          if (key == "progress") {  // not a scene key: the call's own
            progress = py::reinterpret_borrow<py::object>(item.second);
            continue;
          }
          for (char c : key)
            if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'))
              throw Error("law_curves: '" + quote_text(key) + "' is not a law scene's key");
          text += key + " = " + toml_value(key, item.second) + "\n";
        }
        return tabulate(text, "asperity.law_curves", progress);
      },
      "law"_a,
      "A contact law's rough-surface curves (pressure, stiffness, real area fraction against separation),\n"
      "tabulated now by the generator to max_rel_error with the error measured and stored, as tablegen does a\n"
      "law scene (docs/contact-laws.md section 8), served as an asperity.ContactCurves (write it with .write).\n"
      "The keywords are a [[law]] scene's keys: contact_modulus, the law's material (hardness, yield_strength,\n"
      "poisson, ...), distribution, shape, side, height_scale, summit_radius, summit_density, nominal_area,\n"
      "separation=(smin, smax) (dimensionless, origin convention), max_rel_error (1e-10 .. 1e-2). Raises\n"
      "asperity.Error naming the key for a missing, unknown or bad one, or where the curves cannot be\n"
      "tabulated. It runs without the GIL; Ctrl-C stops it (KeyboardInterrupt). progress=callable: called at\n"
      "most once a second with a dict (pass, nodes, checked, intervals, evaluations, elapsed [s]); its\n"
      "exception stops the tabulation. Example:\n"
      "    asperity.law_curves('kogut-etsion', contact_modulus=1.13e11, yield_strength=1e9, poisson=0.3,\n"
      "                        distribution='gaussian', height_scale=1e-6, summit_radius=1e-4,\n"
      "                        summit_density=4e8, nominal_area=1e-4, separation=(0, 4), max_rel_error=1e-6)");
  m.def(
      "tabulate_law_scene", [](const std::string& text) { return tabulate(text, "asperity.tabulate_law_scene"); },
      "text"_a,
      "The same from a law scene's TOML text (a scene file's contents: one [[law]], no [[curve]]).");
}

}  // namespace asperity::python
