#pragma once
// Closest points between the primitives that touch: two segments (bars as capsules) and a point
// and a triangle (a node against a face as a thin shell). Each gives the two closest points as
// weights on the primitives' corners, so that a force there can be shared out to the nodes.
// Exact for every configuration, degenerate ones included (parallel segments, a segment of zero
// length, a point over an edge or a corner), following Ericson, Real-Time Collision Detection
// (2005), §5.1.5 and §5.1.9.
#include <algorithm>
#include <array>

#include "core/dual.hpp"
#include "core/types.hpp"

namespace dinam {

// Both are templates on their scalar (double, or Dual for the contact's stiffness: the weights'
// own derivatives are part of it).

// Closest points p = p0 + s (p1 − p0) and q = q0 + t (q1 − q0), s and t in [0, 1].
template <class T>
struct SegmentPairOf {
  T s = 0.0;
  T t = 0.0;
};
using SegmentPair = SegmentPairOf<double>;

template <class T>
SegmentPairOf<T> closest_points_of_segments(const Eigen::Matrix<T, 3, 1>& p0,
                                            const Eigen::Matrix<T, 3, 1>& p1,
                                            const Eigen::Matrix<T, 3, 1>& q0,
                                            const Eigen::Matrix<T, 3, 1>& q1) {
  using V = Eigen::Matrix<T, 3, 1>;
  const T zero(0.0);
  const T one(1.0);
  const V d1 = p1 - p0;
  const V d2 = q1 - q0;
  const V r = p0 - q0;
  const T a = d1.squaredNorm();
  const T e = d2.squaredNorm();
  const T f = d2.dot(r);
  constexpr double kTiny = 1e-300;
  if (a <= kTiny && e <= kTiny) {
    return {zero, zero};
  }
  if (a <= kTiny) {
    return {zero, std::clamp<T>(f / e, zero, one)};
  }
  const T c = d1.dot(r);
  if (e <= kTiny) {
    return {std::clamp<T>(-c / a, zero, one), zero};
  }
  const T b = d1.dot(d2);
  const T denominator = a * e - b * b;  // ≥ 0; 0 when parallel
  // Parallel segments: any s is as good; s = 0, then t follows.
  T s =
      denominator > 1e-14 * a * e ? std::clamp<T>((b * f - c * e) / denominator, zero, one) : zero;
  T t = (b * s + f) / e;
  if (t < 0.0) {
    t = zero;
    s = std::clamp<T>(-c / a, zero, one);
  } else if (t > 1.0) {
    t = one;
    s = std::clamp<T>((b - c) / a, zero, one);
  }
  return {s, t};
}

// The closest point of triangle (a, b, c) to p, as barycentric weights (wa, wb, wc), each ≥ 0,
// summing to 1.
template <class T>
std::array<T, 3> closest_point_of_triangle(const Eigen::Matrix<T, 3, 1>& p,
                                           const Eigen::Matrix<T, 3, 1>& a,
                                           const Eigen::Matrix<T, 3, 1>& b,
                                           const Eigen::Matrix<T, 3, 1>& c) {
  using V = Eigen::Matrix<T, 3, 1>;
  const T zero(0.0);
  const T one(1.0);
  const V ab = b - a;
  const V ac = c - a;
  const V ap = p - a;
  const T d1 = ab.dot(ap);
  const T d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) {
    return {one, zero, zero};  // corner a
  }
  const V bp = p - b;
  const T d3 = ab.dot(bp);
  const T d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) {
    return {zero, one, zero};  // corner b
  }
  const T vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const T v = d1 / (d1 - d3);  // edge ab
    return {one - v, v, zero};
  }
  const V cp = p - c;
  const T d5 = ab.dot(cp);
  const T d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) {
    return {zero, zero, one};  // corner c
  }
  const T vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const T w = d2 / (d2 - d6);  // edge ac
    return {one - w, zero, w};
  }
  const T va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const T w = (d4 - d3) / ((d4 - d3) + (d5 - d6));  // edge bc
    return {zero, one - w, w};
  }
  const T sum = va + vb + vc;  // inside the face
  if (!(sum > 0.0)) {
    return {one, zero, zero};  // a triangle of zero area: its corner a
  }
  const T v = vb / sum;
  const T w = vc / sum;
  return {one - v - w, v, w};
}

}  // namespace dinam
