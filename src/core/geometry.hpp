#pragma once
// The angles the springs measure, by vector algebra only (no rotation matrices). Both use atan2
// of a sine and a cosine, which stays accurate near 0 and π where acos loses precision.
#include <cmath>
#include <numbers>

#include "core/types.hpp"

namespace dinam {

// atan2(y, x) in (−π, π], about four times faster than glibc's and within a few ulps of it: the
// springs take one per spring per step, which made glibc's atan2 half the cost of a step. Range
// reduction to |t| ≤ 0.66 and a rational approximation of atan there (Cephes, S. L. Moshier:
// the coefficients of its atan.c).
inline double fast_atan2(double y, double x) {
  constexpr double kTan3PiOver8 = 2.41421356237309504880;
  constexpr double kMoreBits = 6.123233995736765886130e-17;  // π/2 − double(π/2)
  const double ay = std::abs(y);
  const double ax = std::abs(x);
  if (ax == 0.0 && ay == 0.0) {
    return std::atan2(y, x);  // signed zeros and the x < 0 case: leave them to libm
  }
  // atan of t = min/max-free ratio ay/ax ∈ [0, ∞], reduced as Cephes does.
  auto atan_small = [](double t) {
    const double z = t * t;
    const double p = ((((-8.750608600031904122785e-01 * z - 1.615753718733365076637e+01) * z -
                        7.500855792314704667340e+01) *
                           z -
                       1.228866684490136173410e+02) *
                          z -
                      6.485021904942025371773e+01);
    const double q = (((((z + 2.485846490142306297962e+01) * z + 1.650270098316988542046e+02) * z +
                        4.328810604912902668951e+02) *
                           z +
                       4.853903996359136964868e+02) *
                          z +
                      1.945506571482613964425e+02);
    return t + t * (z * p / q);
  };
  double angle = 0.0;
  if (ay > kTan3PiOver8 * ax) {  // t > tan(3π/8): π/2 − atan(1/t)
    angle = std::numbers::pi / 2 - atan_small(ax / ay) + kMoreBits;
  } else if (ay > 0.66 * ax) {  // π/4 + atan((t − 1)/(t + 1))
    angle = std::numbers::pi / 4 + atan_small((ay - ax) / (ay + ax)) + 0.5 * kMoreBits;
  } else {
    angle = atan_small(ay / ax);
  }
  if (x < 0.0) {
    angle = std::numbers::pi - angle;
  }
  return std::copysign(angle, y);
}

// The angle at c between the bars c→a and c→b, in [0, π]: π for a straight continuation.
inline double bend_angle(const Vec3& xa, const Vec3& xc, const Vec3& xb) {
  const Vec3 e1 = xa - xc;
  const Vec3 e2 = xb - xc;
  return fast_atan2(e1.cross(e2).norm(), e1.dot(e2));
}

// The dihedral angle about the axis i→j between the planes (a, i, j) and (i, j, b), in (−π, π]:
// with b1 = xi − xa, b2 = xj − xi, b3 = xb − xj, n1 = b1 × b2, n2 = b2 × b3,
// φ = atan2(|b2| b1·n2, n1·n2). It is 0 when a and b lie on the same side in one plane.
inline double dihedral_angle(const Vec3& xa, const Vec3& xi, const Vec3& xj, const Vec3& xb) {
  const Vec3 b1 = xi - xa;
  const Vec3 b2 = xj - xi;
  const Vec3 b3 = xb - xj;
  const Vec3 n1 = b1.cross(b2);
  const Vec3 n2 = b2.cross(b3);
  return fast_atan2(b2.norm() * b1.dot(n2), n1.dot(n2));
}

// An angle difference wrapped into (−π, π], so a twist through ±π is measured the short way.
inline double wrap_angle(double angle) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  angle = std::fmod(angle + std::numbers::pi, kTwoPi);
  if (angle <= 0.0) {
    angle += kTwoPi;
  }
  return angle - std::numbers::pi;
}

}  // namespace dinam
