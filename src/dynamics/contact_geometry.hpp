#pragma once
// Closest points between the primitives that touch: two segments (bars as capsules) and a point
// and a triangle (a node against a face as a thin shell). Each gives the two closest points as
// weights on the primitives' corners, so that a force there can be shared out to the nodes.
// Exact for every configuration, degenerate ones included (parallel segments, a segment of zero
// length, a point over an edge or a corner), following Ericson, Real-Time Collision Detection
// (2005), §5.1.5 and §5.1.9.
#include <algorithm>
#include <array>

#include "core/types.hpp"

namespace dinam {

// Closest points p = p0 + s (p1 − p0) and q = q0 + t (q1 − q0), s and t in [0, 1].
struct SegmentPair {
  double s = 0.0;
  double t = 0.0;
};

inline SegmentPair closest_points_of_segments(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                                              const Vec3& q1) {
  const Vec3 d1 = p1 - p0;
  const Vec3 d2 = q1 - q0;
  const Vec3 r = p0 - q0;
  const double a = d1.squaredNorm();
  const double e = d2.squaredNorm();
  const double f = d2.dot(r);
  constexpr double kTiny = 1e-300;
  if (a <= kTiny && e <= kTiny) {
    return {0.0, 0.0};
  }
  if (a <= kTiny) {
    return {0.0, std::clamp(f / e, 0.0, 1.0)};
  }
  const double c = d1.dot(r);
  if (e <= kTiny) {
    return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  }
  const double b = d1.dot(d2);
  const double denominator = a * e - b * b;  // ≥ 0; 0 when parallel
  // Parallel segments: any s is as good; s = 0, then t follows.
  double s =
      denominator > 1e-14 * a * e ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, t};
}

// The closest point of triangle (a, b, c) to p, as barycentric weights (wa, wb, wc), each ≥ 0,
// summing to 1.
inline std::array<double, 3> closest_point_of_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                                       const Vec3& c) {
  const Vec3 ab = b - a;
  const Vec3 ac = c - a;
  const Vec3 ap = p - a;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) {
    return {1.0, 0.0, 0.0};  // corner a
  }
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) {
    return {0.0, 1.0, 0.0};  // corner b
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);  // edge ab
    return {1.0 - v, v, 0.0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) {
    return {0.0, 0.0, 1.0};  // corner c
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);  // edge ac
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));  // edge bc
    return {0.0, 1.0 - w, w};
  }
  const double sum = va + vb + vc;  // inside the face
  if (!(sum > 0.0)) {
    return {1.0, 0.0, 0.0};  // a triangle of zero area: its corner a
  }
  const double v = vb / sum;
  const double w = vc / sum;
  return {1.0 - v - w, v, w};
}

}  // namespace dinam
