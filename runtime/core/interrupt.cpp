#include "asperity/interrupt.hpp"

#include <chrono>

namespace asperity {
namespace {

thread_local InterruptScope::State* current = nullptr;
thread_local char thread_marker;  // its address tells one thread from another

constexpr long long check_interval_ns = 20'000'000;  // 20 ms: a Ctrl-C answered well within 1 s

long long now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

InterruptScope::InterruptScope(Check check, void* context) : outer_(current) {
  state_.check = check;
  state_.context = context;
  state_.owner = &thread_marker;
  state_.last_check_ns = now_ns();
  current = &state_;
}

InterruptScope::~InterruptScope() { current = outer_; }

bool interrupt_requested() noexcept {
  InterruptScope::State* state = current;
  if (!state) return false;
  if (state->stop.load(std::memory_order_relaxed)) return true;
  if (state->owner != &thread_marker || !state->check) return false;
  // the clock read at every poll (17 ns): a counter between reads would let a loop of slow steps
  // (an FFT iteration of a large map, a second each) go 16 steps unanswered
  const long long now = now_ns();
  if (now - state->last_check_ns < check_interval_ns) return false;
  state->last_check_ns = now;
  if (!state->check(state->context)) return false;
  state->stop.store(true, std::memory_order_relaxed);
  return true;
}

void poll_interrupt() {
  if (current && interrupt_requested()) throw Interrupted();
}

void check_interrupt_now() {
  InterruptScope::State* state = current;
  if (!state) return;
  if (!state->stop.load(std::memory_order_relaxed) && state->owner == &thread_marker && state->check &&
      state->check(state->context))
    state->stop.store(true, std::memory_order_relaxed);
  if (state->stop.load(std::memory_order_relaxed)) throw Interrupted();
}

namespace detail {

InterruptScope::State* current_interrupt_state() noexcept { return current; }

InheritInterrupt::InheritInterrupt(InterruptScope::State* state) noexcept : outer_(current) { current = state; }

InheritInterrupt::~InheritInterrupt() { current = outer_; }

}  // namespace detail
}  // namespace asperity
