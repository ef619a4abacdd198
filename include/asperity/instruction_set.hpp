// The instruction sets the batch path is built for. The batch functions (Curve::value_batch,
// asperity_eval_batch) pick the widest this CPU has; naming one is for tests and benchmarks.
// Results of different instruction sets agree to rounding (fused multiply-adds, and the x86
// sets' own vector exps: within 2.3e-16 of exp), not bitwise.
#pragma once

namespace asperity {

enum class InstructionSet {
  automatic,  // the best available (decided once, from cpuid)
  generic,    // the compiler's baseline for the target (SSE2 on x86-64: 2 doubles a vector)
  avx2,       // AVX2 + FMA: 4 doubles a vector (x86-64 only)
  avx512      // AVX-512 F/DQ/VL: 8 doubles a vector (x86-64 only)
};

bool instruction_set_available(InstructionSet isa) noexcept;
InstructionSet best_instruction_set() noexcept;
const char* to_string(InstructionSet isa) noexcept;

}  // namespace asperity
