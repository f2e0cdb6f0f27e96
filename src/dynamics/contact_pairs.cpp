#include "dynamics/contact_pairs.hpp"

#include <algorithm>

#include "dynamics/contact_geometry.hpp"
#include "dynamics/parallel_loops.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

std::uint64_t pair_key(std::uint64_t kind, Index a, Index b) {
  return kind << 63 | static_cast<std::uint64_t>(a) << 32 | static_cast<std::uint64_t>(b);
}

Box box_of(const Vec3& a, const Vec3& b, double grow) {
  return {a.cwiseMin(b).array() - grow, a.cwiseMax(b).array() + grow};
}

bool objects_may_touch(const ObjectContact& contact, Index object_a, Index object_b) {
  return object_a == object_b
             ? contact.object_self[object_a] != 0
             : contact.object_between[object_a] != 0 && contact.object_between[object_b] != 0;
}

bool bar_broken(const State& state, Index bar) {
  return !state.bar_broken.empty() && state.bar_broken[bar] != 0;
}

bool triangle_broken(const ObjectContact& contact, const State& state, Index triangle) {
  return !state.face_broken.empty() && state.face_broken[contact.triangle_face[triangle]] != 0;
}

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

// Appends the pair to the candidates when its closest points are within reach + 2 skin.
void add_if_near(const ObjectContact& contact, const std::vector<Vec3>& x,
                 const ContactCandidate& pair, std::vector<ContactCandidate>& candidates) {
  const double near = contact_reach(contact, pair.key) + 2.0 * contact.skin;
  if (separation_of(pair.nodes, closest_weights(pair, x), x).squaredNorm() < near * near) {
    candidates.push_back(pair);
  }
}

// The bars' and triangles' boxes grown by their radii and the skin, and the grids over them.
void file_boxes(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  ObjectContactWorkspace& work = state.object_contact;
  const std::vector<Vec3>& x = state.x;
  work.bar_boxes.resize(model.bar_count());
  work.bar_used.assign(model.bar_count(), 0);
  for (const Index b : contact.bars) {
    if (!bar_broken(state, b)) {
      work.bar_boxes[b] = box_of(x[model.bar_nodes[2 * b]], x[model.bar_nodes[2 * b + 1]],
                                 contact.bar_radius[b] + contact.skin);
      work.bar_used[b] = 1;
    }
  }
  const auto triangles = static_cast<Index>(contact.triangle_face.size());
  work.triangle_boxes.resize(triangles);
  work.triangle_used.assign(triangles, 0);
  for (Index t = 0; t < triangles; ++t) {
    if (!triangle_broken(contact, state, t)) {
      const Index* corners = &contact.triangles[3 * t];
      const double grow = contact.triangle_radius[t] + contact.skin;
      Box box = box_of(x[corners[0]], x[corners[1]], grow);
      box.min = box.min.cwiseMin(x[corners[2]] - Vec3::Constant(grow));
      box.max = box.max.cwiseMax(x[corners[2]] + Vec3::Constant(grow));
      work.triangle_boxes[t] = box;
      work.triangle_used[t] = 1;
    }
  }
  double widest_point = 0.0;
  for (const Index p : contact.points) {
    widest_point = std::max(widest_point, 2.0 * (contact.point_radius[p] + contact.skin));
  }
  work.bar_grid.build(work.bar_boxes, work.bar_used, 0.0);
  work.triangle_grid.build(work.triangle_boxes, work.triangle_used, widest_point);
}

// Every pair within reach + 2 skin at the current positions, in key order.
void find_candidates(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  ObjectContactWorkspace& work = state.object_contact;
  const std::vector<Vec3>& x = state.x;
  file_boxes(model, state);
  work.candidates.clear();
  for (const Index a : contact.bars) {
    if (work.bar_used[a] == 0) {
      continue;
    }
    const Index a0 = model.bar_nodes[2 * a];
    const Index a1 = model.bar_nodes[2 * a + 1];
    const Index object_a = model.node_object[a0];
    const bool a_free = !model.pinned(a0) || !model.pinned(a1);
    work.bar_grid.visit_overlapping(work.bar_boxes[a], [&](Index b) {
      const Index b0 = model.bar_nodes[2 * b];
      const Index b1 = model.bar_nodes[2 * b + 1];
      if (b <= a || a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1 ||
          !objects_may_touch(contact, object_a, model.node_object[b0]) ||
          (!a_free && model.pinned(b0) && model.pinned(b1)) ||
          (object_a == model.node_object[b0] &&
           (contact.joined(a0, b0) || contact.joined(a0, b1) || contact.joined(a1, b0) ||
            contact.joined(a1, b1)))) {
        return;
      }
      add_if_near(contact, x, {pair_key(kBarBarContact, a, b), {a0, a1, b0, b1}}, work.candidates);
    });
  }
  for (const Index p : contact.points) {
    const Box box = box_of(x[p], x[p], contact.point_radius[p] + contact.skin);
    const Index object_p = model.node_object[p];
    work.triangle_grid.visit_overlapping(box, [&](Index t) {
      const Index* c = &contact.triangles[3 * t];
      if (p == c[0] || p == c[1] || p == c[2] ||
          !objects_may_touch(contact, object_p, model.node_object[c[0]]) ||
          (model.pinned(p) && model.pinned(c[0]) && model.pinned(c[1]) && model.pinned(c[2])) ||
          (object_p == model.node_object[c[0]] &&
           (contact.joined(p, c[0]) || contact.joined(p, c[1]) || contact.joined(p, c[2])))) {
        return;
      }
      add_if_near(contact, x, {pair_key(kPointTriangleContact, p, t), {p, c[0], c[1], c[2]}},
                  work.candidates);
    });
  }
  std::sort(work.candidates.begin(), work.candidates.end(),
            [](const ContactCandidate& a, const ContactCandidate& b) { return a.key < b.key; });
  work.reference_x = x;
  work.candidates_found = true;
  ++work.searches;
}

// True once some node of the contact has moved by more than the skin since the search.
bool moved_past_skin(const Model& model, const State& state) {
  const ObjectContactWorkspace& work = state.object_contact;
  const double skin_squared = model.contact.skin * model.contact.skin;
  for (const Index p : model.contact.points) {
    if ((state.x[p] - work.reference_x[p]).squaredNorm() > skin_squared) {
      return true;
    }
  }
  return false;
}

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

void find_touching_pairs(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  ObjectContactWorkspace& work = state.object_contact;
  if (!work.candidates_found || moved_past_skin(model, state)) {
    find_candidates(model, state);
  }
  // Each candidate's closest points, in parallel (each writes its own slot), then the touching
  // ones in candidate order.
  const std::vector<Vec3>& x = state.x;
  const auto count = static_cast<Index>(work.candidates.size());
  work.checked.resize(work.candidates.size());
  for_each_index(count, [&](Index k) {
    const ContactCandidate& pair = work.candidates[k];
    ContactPoint& point = work.checked[k];
    const bool bar_pair = (pair.key >> 63) == kBarBarContact;
    const Index a = contact_side_a(pair.key);
    const Index b = contact_side_b(pair.key);
    point.key = 0;  // not touching
    if (bar_pair ? bar_broken(state, a) || bar_broken(state, b)
                 : triangle_broken(contact, state, b)) {
      return;  // torn since the search
    }
    const std::array<double, 4> weights = closest_weights(pair, x);
    const Vec3 separation = separation_of(pair.nodes, weights, x);
    const double reach = contact_reach(contact, pair.key);
    if (separation.squaredNorm() < reach * reach) {
      point.key = pair.key;
      point.features = features_of(pair, weights);
      point.nodes = pair.nodes;
      point.weights = weights;
      point.separation = separation;
    }
  });
  work.touching.clear();
  for (const ContactPoint& point : work.checked) {
    if (point.key != 0) {
      work.touching.push_back(point);
    }
  }
  // One contact per pair of features: the first pair (by key) that names them.
  std::sort(work.touching.begin(), work.touching.end(),
            [](const ContactPoint& a, const ContactPoint& b) {
              return a.features != b.features ? a.features < b.features : a.key < b.key;
            });
  const auto last = std::unique(
      work.touching.begin(), work.touching.end(),
      [](const ContactPoint& a, const ContactPoint& b) { return a.features == b.features; });
  work.touching.erase(last, work.touching.end());
}

}  // namespace dinam
