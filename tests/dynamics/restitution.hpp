#pragma once
// The restitution law of contact, in closed form, for the tests that check rebounds against it.
#include <cmath>
#include <numbers>

namespace dinam::test {

// The restitution of a mass on a spring and a damper of ratio ζ < 1/√2 whose force is clipped at
// zero (it only pushes): the contact ends when k x + c ẋ = 0, at ω_d t = π − atan(2ζ√(1−ζ²) / (1 −
// 2ζ²)), so e = exp(−ζ ω t) |cos ω_d t − ζ/√(1−ζ²) sin ω_d t|.
inline double restitution_of(double zeta) {
  const double root = std::sqrt(1.0 - zeta * zeta);
  const double phase = std::numbers::pi - std::atan(2.0 * zeta * root / (1.0 - 2.0 * zeta * zeta));
  return std::exp(-zeta * phase / root) * std::abs(std::cos(phase) - zeta / root * std::sin(phase));
}

}  // namespace dinam::test
