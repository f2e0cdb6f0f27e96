#pragma once
// The angles the springs measure, by vector algebra only (no rotation matrices). Both use atan2
// of a sine and a cosine, which stays accurate near 0 and π where acos loses precision.
#include <cmath>
#include <numbers>

#include "core/types.hpp"

namespace dinam {

// The angle at c between the bars c→a and c→b, in [0, π]: π for a straight continuation.
inline double bend_angle(const Vec3& xa, const Vec3& xc, const Vec3& xb) {
  const Vec3 e1 = xa - xc;
  const Vec3 e2 = xb - xc;
  return std::atan2(e1.cross(e2).norm(), e1.dot(e2));
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
  return std::atan2(b2.norm() * b1.dot(n2), n1.dot(n2));
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
