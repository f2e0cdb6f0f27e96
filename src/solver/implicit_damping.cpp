#include "solver/implicit_damping.hpp"

#include <cmath>
#include <complex>
#include <numbers>

namespace dinam {

double amplitude_kept_per_period(ImplicitScheme scheme, double steps_per_period) {
  const double omega_h = 2.0 * std::numbers::pi / steps_per_period;
  const std::complex<double> z(0.0, omega_h);
  const std::complex<double> root = scheme == ImplicitScheme::kBdf2
                                        ? (2.0 + std::sqrt(1.0 + 2.0 * z)) / (3.0 - 2.0 * z)
                                        : 1.0 / (1.0 - z);
  return std::pow(std::abs(root), steps_per_period);
}

}  // namespace dinam
