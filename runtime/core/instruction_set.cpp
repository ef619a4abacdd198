// Which instruction sets this CPU has (cpuid via __builtin_cpu_supports), decided once; the
// kernels' dispatch (kernel/kernels_dispatch.cpp) picks by it.
#include "asperity/instruction_set.hpp"

namespace asperity {

bool instruction_set_available(InstructionSet isa) noexcept {
  switch (isa) {
    case InstructionSet::automatic:
    case InstructionSet::generic: return true;
#if ASPERITY_X86_KERNELS
    case InstructionSet::avx2: return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case InstructionSet::avx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
             __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    case InstructionSet::avx2:
    case InstructionSet::avx512: return false;
#endif
  }
  return false;
}

InstructionSet best_instruction_set() noexcept {
  static const InstructionSet best = instruction_set_available(InstructionSet::avx512) ? InstructionSet::avx512
                                     : instruction_set_available(InstructionSet::avx2) ? InstructionSet::avx2
                                                                                        : InstructionSet::generic;
  return best;
}

const char* to_string(InstructionSet isa) noexcept {
  switch (isa) {
    case InstructionSet::automatic: return "automatic";
    case InstructionSet::generic: return "generic";
    case InstructionSet::avx2: return "avx2";
    case InstructionSet::avx512: return "avx512";
  }
  return "unknown";
}

}  // namespace asperity
