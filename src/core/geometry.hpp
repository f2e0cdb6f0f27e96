#pragma once
// The angles the springs measure, by vector algebra only (no rotation matrices). Both use atan2
// of a sine and a cosine, which stays accurate near 0 and π where acos loses precision.
#include <cmath>
#include <numbers>

#include "core/types.hpp"

namespace dinam {

// The dot and cross products of 3-vectors in plain scalar arithmetic (of double, or of Dual for
// the kernels' derivatives: core/dual.hpp). Eigen's own (and its norms)
// work on SSE packets of two coordinates, which keeps the compiler from vectorising the spring
// loops across springs (spring_block.hpp); these it vectorises one spring per SIMD lane.
template <class A, class B>
[[gnu::always_inline]] inline auto dot3(const Eigen::MatrixBase<A>& a,
                                        const Eigen::MatrixBase<B>& b) {
  return a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
}
template <class A>
[[gnu::always_inline]] inline auto norm3(const Eigen::MatrixBase<A>& a) {
  using std::sqrt;
  return sqrt(dot3(a, a));
}
template <class A, class B>
[[gnu::always_inline]] inline auto cross3(const Eigen::MatrixBase<A>& a,
                                          const Eigen::MatrixBase<B>& b) {
  return Eigen::Matrix<typename A::Scalar, 3, 1>(
      a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x());
}

// atan2(y, x) in [−π, π], about four times faster than glibc's and within a few ulps of it: the
// springs take one per spring per step, which made glibc's atan2 half the cost of a step. It is
// written with selects only, no branches, so that the loops over springs that call it vectorise.
// The ratio of the smaller to the larger of |x|, |y| is reduced to |t| ≤ tan(π/8) (atan t =
// π/4 + atan((t − 1)/(t + 1)) above it), where a rational approximation of atan (Cephes, S. L.
// Moshier: the coefficients of its atan.c, made for |t| ≤ 0.66) is accurate to an ulp.
//
// It comes in two halves so that a spring kernel can fold the one quotient of the reduction,
// t = top / bottom, into a reciprocal it takes anyway (one division where there were several):
// atan2_reduce gives top and bottom, atan2_finish the angle from t.
template <class T>
struct Atan2Reduction {
  T top;       // t's numerator
  T bottom;    // t's denominator: > 0 (1 for x = y = 0, where top is 0 too)
  bool steep;  // |y| > |x|
  bool upper;  // reduced by π/4
  T x, y;
};
template <class T>
[[gnu::always_inline]] inline Atan2Reduction<T> atan2_reduce(const T& y, const T& x) {
  using std::abs;
  constexpr double kTanPiOver8 = 0.41421356237309504880;
  const T ax = abs(x);
  const T ay = abs(y);
  const bool steep = ay > ax;
  const T small = steep ? ax : ay;
  const T large = steep ? ay : ax;
  const bool upper = small > kTanPiOver8 * large;
  const T top = upper ? T(small - large) : small;
  const T bottom = upper ? T(small + large) : large;
  return {top, bottom > 0.0 ? bottom : T(1.0), steep, upper, x, y};
}
template <class T>
[[gnu::always_inline]] inline T atan2_finish(const Atan2Reduction<T>& r, const T& t) {
  using std::copysign;
  const T z = t * t;
  const T p = ((((-8.750608600031904122785e-01 * z - 1.615753718733365076637e+01) * z -
                 7.500855792314704667340e+01) *
                    z -
                1.228866684490136173410e+02) *
                   z -
               6.485021904942025371773e+01);
  const T q = (((((z + 2.485846490142306297962e+01) * z + 1.650270098316988542046e+02) * z +
                 4.328810604912902668951e+02) *
                    z +
                4.853903996359136964868e+02) *
                   z +
               1.945506571482613964425e+02);
  T angle = (r.upper ? std::numbers::pi / 4 : 0.0) + (t + t * (z * p / q));
  angle = r.steep ? T(std::numbers::pi / 2 - angle) : angle;
  angle = r.x < 0.0 ? T(std::numbers::pi - angle) : angle;
  return copysign(angle, r.y);
}
[[gnu::always_inline]] inline double fast_atan2(double y, double x) {
  const Atan2Reduction<double> r = atan2_reduce(y, x);
  return atan2_finish(r, r.top / r.bottom);
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

// An angle difference wrapped into [−π, π), so a twist through ±π is measured the short way
// (by a product with 1/2π rather than a quotient: a division costs as much as ten products in
// the spring loops).
template <class T>
[[gnu::always_inline]] inline T wrap_angle(const T& angle) {
  using std::floor;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  constexpr double kInverseTwoPi = 1.0 / kTwoPi;
  return angle - kTwoPi * floor((angle + std::numbers::pi) * kInverseTwoPi);
}

}  // namespace dinam
