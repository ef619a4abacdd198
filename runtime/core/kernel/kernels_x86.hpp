// The kernel set of the x86 builds, one definition compiled by each of them (kernels_avx2.cpp,
// kernels_avx512.cpp): internal linkage, so each build's set points at its own copies.
#pragma once
#include "batch_x86.hpp"
#include "contact4_x86.hpp"

namespace asperity::detail {
namespace {
constexpr Kernels x86_kernels{scalar_value<ScalarMath>,
                              contact4_x86,
                              contact_products_x86<ContactInputs::factors>,
                              contact_products_x86<ContactInputs::surface>,
                              contact_entry<contact_products_x86<ContactInputs::factors>>,
                              contact_entry<contact_products_x86<ContactInputs::surface>>,
                              block<X86Passes>,
                              X86Passes::exps};
}  // namespace
}  // namespace asperity::detail
