#include "dynamics/contact/contact_pairs.hpp"

#include <algorithm>
#include <optional>

#include "dynamics/contact/contact_candidates.hpp"
#include "dynamics/contact/contact_closest.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// The features whose closest points a pair's weights name: a node against a node, a node against
// a bar's inside, a node against a triangle's inside, or the insides of two bars. Several pairs
// name the same features where meshes meet at a node or an edge (a node over a vertex of a cloth
// is over all six of its triangles); each is one contact.
ContactFeatures features_of(const ContactCandidate& pair, const std::array<double, 4>& weights) {
  const std::array<Index, 4>& n = pair.nodes;
  // The nodes with a weight on each side (weights are exactly 0 or 1 where a closest point lies
  // on a corner or an edge: the kernels clamp, they do not round).
  Index a[2];
  Index b[3];
  int a_count = 0;
  int b_count = 0;
  const int a_nodes = (pair.key >> 63) == kBarBarContact ? 2 : 1;
  for (int j = 0; j < 4; ++j) {
    if (weights[j] != 0.0) {
      (j < a_nodes ? a[a_count++] : b[b_count++]) = n[j];
    }
  }
  auto sorted = [](Index u, Index v) { return std::pair{std::min(u, v), std::max(u, v)}; };
  if (a_count == 1 && b_count == 1) {
    const auto [p, q] = sorted(a[0], b[0]);
    return {ContactFeatures::kNodeNode, p, q, -1};
  }
  if (a_count == 1 && b_count == 2) {
    const auto [u, v] = sorted(b[0], b[1]);
    return {ContactFeatures::kNodeEdge, a[0], u, v};
  }
  if (a_count == 2 && b_count == 1) {
    const auto [u, v] = sorted(a[0], a[1]);
    return {ContactFeatures::kNodeEdge, b[0], u, v};
  }
  if (a_count == 1) {  // a node against a triangle's inside
    return {ContactFeatures::kNodeTriangle, a[0], contact_side_b(pair.key), -1};
  }
  return {ContactFeatures::kEdgeEdge, contact_side_a(pair.key), contact_side_b(pair.key), -1};
}

}  // namespace

double contact_reach(const ObjectContact& contact, std::uint64_t key) {
  const Index a = contact_side_a(key);
  const Index b = contact_side_b(key);
  return (key >> 63) == kBarBarContact ? contact.bar_radius[a] + contact.bar_radius[b]
                                       : contact.point_radius[a] + contact.triangle_radius[b];
}

void find_touching_pairs(const Model& model, State& state, PairMerging merging) {
  const ObjectContact& contact = model.contact;
  refresh_candidates(model, state);
  ObjectContactWorkspace& work = state.object_contact;
  // Each candidate's closest points, in parallel; the touching ones in candidate order.
  const std::vector<Vec3>& x = state.x;
  auto check = [&](Index k, std::vector<ContactPoint>& list) {
    const ContactCandidate& pair = work.candidates[k];
    const Index a = contact_side_a(pair.key);
    const Index b = contact_side_b(pair.key);
    if ((pair.key >> 63) == kBarBarContact ? bar_broken(state, a) || bar_broken(state, b)
                                           : triangle_broken(contact, state, b)) {
      return;  // torn since the search
    }
    if (const std::optional<Closest> closest =
            closest_within(pair, x, contact_reach(contact, pair.key))) {
      ContactPoint& point = list.emplace_back();
      point.key = pair.key;
      point.features = features_of(pair, closest->weights);
      point.nodes = pair.nodes;
      point.weights = closest->weights;
      point.separation = closest->separation;
    }
  };
  work.touching.clear();
  gather_in_parallel(static_cast<Index>(work.candidates.size()), work.thread_touching,
                     work.touching, check);
  std::sort(work.touching.begin(), work.touching.end(),
            [](const ContactPoint& a, const ContactPoint& b) {
              return a.features != b.features ? a.features < b.features : a.key < b.key;
            });
  if (merging == PairMerging::kEveryPair) {
    return;
  }
  // One contact per pair of features: the first pair (by key) that names them.
  const auto last = std::unique(
      work.touching.begin(), work.touching.end(),
      [](const ContactPoint& a, const ContactPoint& b) { return a.features == b.features; });
  work.touching.erase(last, work.touching.end());
}

}  // namespace dinam
