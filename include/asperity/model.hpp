// The former name of integrals.hpp (deprecated, kept for existing code: to be removed). "Model"
// names the contact model (ContactModel, contact_model.hpp) and, in topography, a fitted height
// distribution (HeightModel); the integrals' vocabulary is integrals.hpp.
#pragma once
#include "asperity/integrals.hpp"
