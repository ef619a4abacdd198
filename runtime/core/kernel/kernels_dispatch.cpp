// Which batch kernel runs: the widest vectors this CPU has (best_instruction_set,
// core/instruction_set.cpp), or the one a caller names.
#include "kernels.hpp"

namespace asperity {
namespace detail {

const Kernels& kernels_for(InstructionSet isa) noexcept {
  if (isa == InstructionSet::automatic || !instruction_set_available(isa)) isa = best_instruction_set();
  switch (isa) {
#if ASPERITY_X86_KERNELS
    case InstructionSet::avx512: return avx512_kernels;
    case InstructionSet::avx2: return avx2_kernels;
#endif
    default: return generic_kernels;
  }
}

Contact4 best_contact4() noexcept { return kernels_for(InstructionSet::automatic).contact4; }

}  // namespace detail
}  // namespace asperity
