// Ctrl-C in a long call (a law tabulation, an exact contact, a surface analysis, a table written):
// the work runs without the GIL inside an asperity::InterruptScope whose check takes the GIL and
// runs Python's signal handlers (PyErr_CheckSignals). Once a handler raises (KeyboardInterrupt by
// default), the library's next poll_interrupt() throws asperity::Interrupted, the work unwinds (an
// output being written is removed: asperity/output.hpp), and at the binding's boundary, the GIL
// held again, the handler's exception is what Python sees.
#pragma once
#include <pybind11/pybind11.h>

#include <optional>
#include <type_traits>
#include <utility>

#include "asperity/interrupt.hpp"

namespace asperity::python {

// An InterruptScope asking Python's signal handlers; made on the thread that runs the work, with
// the GIL released (the check takes it for a moment, at most every 20 ms).
class PythonInterruptScope {
 public:
  PythonInterruptScope() : scope_(&signalled, &raised_) {}
  // Whether a handler raised (its exception is pending on this thread's Python state).
  bool raised() const { return raised_; }

 private:
  static bool signalled(void* raised) {
    pybind11::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) return false;
    *static_cast<bool*>(raised) = true;
    return true;
  }
  bool raised_ = false;
  InterruptScope scope_;
};

// The exception Python is given for an Interrupted: the one a signal handler raised (pending on
// this thread), else KeyboardInterrupt. Call with the GIL held.
[[noreturn]] inline void raise_interrupted() {
  if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
  throw pybind11::error_already_set();
}

// Runs work() (returning nothing) without the GIL, interruptible by Ctrl-C; see interruptible().
template <class Work>
void run_interruptible(Work&& work) {
  bool raised = false;
  try {
    pybind11::gil_scoped_release unlocked;
    PythonInterruptScope scope;
    struct NoteRaised {  // read as the scope closes, whichever way the work ends
      const PythonInterruptScope& scope;
      bool& raised;
      ~NoteRaised() { raised = scope.raised(); }
    } note{scope, raised};
    work();
  } catch (const Interrupted&) {
    raise_interrupted();  // the GIL is held again here
  } catch (...) {
    if (raised) raise_interrupted();
    throw;
  }
  if (raised) raise_interrupted();  // asked to stop after the last poll: the handler's exception wins
}

// Runs work() without the GIL, interruptible by Ctrl-C, and returns its result. What it reads must
// be its own (captured by value with the GIL held), never an object another Python thread can
// change. A signal handler's exception wins over the work's result or error: it was asked to stop.
template <class Work>
auto interruptible(Work&& work) {
  using Result = decltype(work());
  if constexpr (std::is_void_v<Result>) {
    run_interruptible(std::forward<Work>(work));
  } else {
    std::optional<Result> result;
    run_interruptible([&] { result.emplace(work()); });
    return std::move(*result);
  }
}

}  // namespace asperity::python
