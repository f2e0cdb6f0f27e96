#pragma once
// sin(θ) without branches, so that loops over many points vectorise (the turbulence of the wind
// takes twelve per point per step, and glibc's sin, about 20 ns each, made it five times the
// cost of every spring together).
#include <cmath>
#include <numbers>

namespace dinam {

// sin θ to within about 2e-16 of |θ|'s scale for |θ| up to about 1e6 (the wind's phases stay
// within a few hundred radians). θ = qπ + r with q an integer and |r| ≤ π/2; sin θ = (−1)^q sin r.
// π is split in three parts (Cody and Waite) so that r keeps its bits: q·kPiHigh is exact for
// |q| < 2^21, kPiHigh having 32 significant bits. sin r is its Taylor polynomial to r^19, whose
// remainder is below (π/2)^21 / 21! ≈ 2.5e-16 on |r| ≤ π/2.
// Only +, −, × and floor: the same bits in every SIMD lane and in scalar code, on every x86-64
// build (FMA contraction is off, CMakeLists.txt), so a vectorised loop and a scalar call agree.
[[gnu::always_inline]] inline double fast_sin(double theta) {
  constexpr double kPiHigh = 0x1.921fb544p+1;           // π to 32 bits, 3.1415926534682512
  constexpr double kPiMiddle = 1.2154201013012384e-10;  // the next 53 bits
  constexpr double kPiLow = 7.0431197303664e-27;        // the rest, to about 4e-43
  const double q = std::floor(theta * std::numbers::inv_pi + 0.5);
  const double r = ((theta - q * kPiHigh) - q * kPiMiddle) - q * kPiLow;
  // (−1)^q: q/2 has a fractional part of 0 (q even) or ½ (q odd).
  const double half = 0.5 * q;
  const double sign = 1.0 - 4.0 * (half - std::floor(half));
  const double z = r * r;
  // 1/3!, 1/5!, … 1/19! with alternating signs, by Horner's rule from the smallest.
  double p = -8.22063524662433e-18;    // −1/19!
  p = p * z + 2.8114572543455206e-15;  // 1/17!
  p = p * z - 7.647163731819816e-13;   // −1/15!
  p = p * z + 1.6059043836821613e-10;  // 1/13!
  p = p * z - 2.505210838544172e-08;   // −1/11!
  p = p * z + 2.7557319223985893e-06;  // 1/9!
  p = p * z - 0.0001984126984126984;   // −1/7!
  p = p * z + 0.008333333333333333;    // 1/5!
  p = p * z - 0.16666666666666666;     // −1/3!
  return sign * (r + r * (z * p));
}

}  // namespace dinam
