// Long computations that can be stopped: a tabulation, an exact contact, a surface analysis.
//
// A caller that can be interrupted (a command on SIGINT/SIGTERM, a Python call on Ctrl-C) opens
// an InterruptScope with a check of its own; the long loops call poll_interrupt(), which throws
// Interrupted once the check says stop. The exception unwinds like any other error, so every
// output half written is removed on the way out (asperity/output.hpp). Jobs that
// detail::parallel_for hands to other threads see their caller's scope.
//
// Cheap: a thread-local read (and, inside a scope, a steady-clock read, ~20 ns), so a poll belongs
// in loops whose steps cost a microsecond or more (a quadrature, an iteration, an ODE step), not
// in an integrand of a few nanoseconds. The caller's check runs on the scope's own thread, at
// most every 20 ms of steady time.
#pragma once
#include <atomic>

#include "asperity/error.hpp"

namespace asperity {

// What poll_interrupt() throws: the run was asked to stop. Nothing it was writing is left.
class Interrupted : public Error {
 public:
  Interrupted() : Error("interrupted") {}
};

class InterruptScope {
 public:
  // check(context) returns true to stop; called only on the thread that made the scope. It may
  // block briefly (Python takes the GIL in it).
  using Check = bool (*)(void* context);
  InterruptScope(Check check, void* context);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  // The state other threads share (detail::parallel_for's workers).
  struct State {
    Check check = nullptr;
    void* context = nullptr;
    const void* owner = nullptr;  // the owning thread's marker
    std::atomic<bool> stop{false};
    long long last_check_ns = 0;
  };

 private:
  State state_;
  State* outer_;
};

// Throws Interrupted if this thread's scope (its own, or the one it inherited) was asked to stop.
void poll_interrupt();

// As poll_interrupt(), but asks the scope's check now (before a step that cannot be undone:
// renaming the outputs into place).
void check_interrupt_now();

// Whether a stop was asked, without throwing (for code that must finish a step first).
bool interrupt_requested() noexcept;

namespace detail {
// parallel_for: the caller's scope, carried into each worker thread for the worker's lifetime.
InterruptScope::State* current_interrupt_state() noexcept;
class InheritInterrupt {
 public:
  explicit InheritInterrupt(InterruptScope::State* state) noexcept;
  ~InheritInterrupt();
  InheritInterrupt(const InheritInterrupt&) = delete;
  InheritInterrupt& operator=(const InheritInterrupt&) = delete;

 private:
  InterruptScope::State* outer_;
};
}  // namespace detail

}  // namespace asperity
