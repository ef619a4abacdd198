// The kernels built for the compiler's baseline (see kernels.hpp). With two doubles a vector
// (and no 64-bit variable shifts) vector code does not pay beyond the positions: the quintics
// and the inline exp run one call at a time (bench_lookup BM_StdExp / BM_FastExp: the inline
// exp is faster than the C library's, which also slows below e^-512 and for subnormal results).
#include "kernels.hpp"

namespace asperity::detail {
const Kernels generic_kernels{
    scalar_value<ScalarMath>,
    contact4<ScalarMath>,
    contact_products<ScalarMath, ContactInputs::factors>,
    contact_products<ScalarMath, ContactInputs::surface>,
    contact_entry<contact_products<ScalarMath, ContactInputs::factors>>,
    contact_entry<contact_products<ScalarMath, ContactInputs::surface>>,
    block<ScalarPasses>,
    ScalarPasses::exps};
}
