// The floating-point type of all geometry math (thesis 3.3.1, Table 4.4).
// Chosen at configure time: cmake -DRT_REAL=float|double. Colours are always float.
#pragma once

#include <cstdint>
#include <limits>

namespace rt {

#ifdef RT_REAL_FLOAT
using Real = float;
#else
using Real = double;
#endif

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();
constexpr Real kPi = Real(3.14159265358979323846);

constexpr const char* realTypeName() { return sizeof(Real) == sizeof(float) ? "float" : "double"; }

}  // namespace rt
