// The permittivity of free space, shared by the Laplace solver and the parallel-plate law.
#pragma once
#include "core/types.hpp"

namespace rfmems {

inline constexpr Real kVacuumPermittivity = 8.8541878128e-12;  // F/m (CODATA 2018)

}  // namespace rfmems
