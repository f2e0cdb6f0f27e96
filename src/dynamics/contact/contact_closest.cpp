#include "dynamics/contact/contact_closest.hpp"

#include "core/closest_points.hpp"

namespace dinam {
namespace {

// The closest points' weights of a pair, A's positive and B's negative, at positions x.
std::array<double, 4> closest_weights(const ContactCandidate& pair, const std::vector<Vec3>& x) {
  const std::array<Index, 4>& n = pair.nodes;
  if ((pair.key >> 63) == kBarBarContact) {
    const SegmentPair c = closest_points_of_segments(x[n[0]], x[n[1]], x[n[2]], x[n[3]]);
    return {1.0 - c.s, c.s, c.t - 1.0, -c.t};
  }
  const std::array<double, 3> w = closest_point_of_triangle(x[n[0]], x[n[1]], x[n[2]], x[n[3]]);
  return {1.0, -w[0], -w[1], -w[2]};
}

Vec3 separation_of(const std::array<Index, 4>& nodes, const std::array<double, 4>& weights,
                   const std::vector<Vec3>& x) {
  Vec3 separation = Vec3::Zero();
  for (int j = 0; j < 4; ++j) {
    separation += weights[j] * x[nodes[j]];
  }
  return separation;
}

// True when the boxes of the pair's two sides are `distance` or more apart along some axis: then
// so are their closest points. Two layers of cloth lying one over the other are near enough to
// be candidates but, mostly, apart by this cheap test.
bool boxes_apart(const ContactCandidate& pair, const std::vector<Vec3>& x, double distance) {
  const std::array<Index, 4>& n = pair.nodes;
  const int a_nodes = (pair.key >> 63) == kBarBarContact ? 2 : 1;
  Vec3 a_min = x[n[0]];
  Vec3 a_max = a_min;
  Vec3 b_min = x[n[a_nodes]];
  Vec3 b_max = b_min;
  for (int j = 1; j < 4; ++j) {
    const Vec3& p = x[n[j]];
    if (j < a_nodes) {
      a_min = a_min.cwiseMin(p);
      a_max = a_max.cwiseMax(p);
    } else if (j > a_nodes) {
      b_min = b_min.cwiseMin(p);
      b_max = b_max.cwiseMax(p);
    }
  }
  const Vec3 gap = (a_min - b_max).cwiseMax(b_min - a_max);
  return gap.maxCoeff() >= distance;
}

}  // namespace

std::optional<Closest> closest_within(const ContactCandidate& pair, const std::vector<Vec3>& x,
                                      double distance) {
  if (boxes_apart(pair, x, distance)) {
    return std::nullopt;
  }
  const std::array<double, 4> weights = closest_weights(pair, x);
  const Vec3 separation = separation_of(pair.nodes, weights, x);
  if (separation.squaredNorm() >= distance * distance) {
    return std::nullopt;
  }
  return Closest{weights, separation};
}

}  // namespace dinam
