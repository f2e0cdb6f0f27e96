#include "dynamics/contact_pairs.hpp"

#include <algorithm>
#include <optional>

#include "core/thread_team.hpp"
#include "dynamics/contact_geometry.hpp"
#include "dynamics/parallel_loops.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// body(i) for every item in [0, count), each writing only data of its own: on the team when
// there are enough of them.
template <class Body>
void for_each_item(Index count, const Body& body) {
  thread_team().run(
      [&](const TeamMember& member) {
        const auto [first, last] = member.share(count, 8);
        for (Index i = first; i < last; ++i) {
          body(i);
        }
      },
      count < kMinParallelItems);
}

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

// The pair's closest points' weights and separation when they are nearer than `distance`.
struct Closest {
  std::array<double, 4> weights;
  Vec3 separation;
};
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

// Appends the pair to the candidates when its closest points are within reach + 2 skin.
void add_if_near(const ObjectContact& contact, double skin, const std::vector<Vec3>& x,
                 const ContactCandidate& pair, std::vector<ContactCandidate>& candidates) {
  if (closest_within(pair, x, contact_reach(contact, pair.key) + 2.0 * skin)) {
    candidates.push_back(pair);
  }
}

// The bars' and triangles' boxes grown by their radii and the skin, and the grids over them.
void file_boxes(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  ObjectContactWorkspace& work = state.object_contact;
  const std::vector<Vec3>& x = state.x;
  const double skin = work.skin;
  work.bar_boxes.resize(model.bar_count());
  work.bar_used.assign(model.bar_count(), 0);
  for_each_item(static_cast<Index>(contact.bars.size()), [&](Index k) {
    const Index b = contact.bars[k];
    if (!bar_broken(state, b)) {
      work.bar_boxes[b] = box_of(x[model.bar_nodes[2 * b]], x[model.bar_nodes[2 * b + 1]],
                                 contact.bar_radius[b] + skin);
      work.bar_used[b] = 1;
    }
  });
  const auto triangles = static_cast<Index>(contact.triangle_face.size());
  work.triangle_boxes.resize(triangles);
  work.triangle_used.assign(triangles, 0);
  for_each_item(triangles, [&](Index t) {
    if (!triangle_broken(contact, state, t)) {
      const Index* corners = &contact.triangles[3 * t];
      const double grow = contact.triangle_radius[t] + skin;
      Box box = box_of(x[corners[0]], x[corners[1]], grow);
      box.min = box.min.cwiseMin(x[corners[2]] - Vec3::Constant(grow));
      box.max = box.max.cwiseMax(x[corners[2]] + Vec3::Constant(grow));
      work.triangle_boxes[t] = box;
      work.triangle_used[t] = 1;
    }
  });
  double widest_point = 0.0;
  for (const Index p : contact.points) {
    widest_point = std::max(widest_point, 2.0 * (contact.point_radius[p] + skin));
  }
  work.bar_grid.build(work.bar_boxes, work.bar_used, 0.0);
  work.triangle_grid.build(work.triangle_boxes, work.triangle_used, widest_point);
}

// gather(item, list) for every item in [0, count), appending what it finds to `list`; in
// contiguous runs of items, one per member of the team, each into its own list of `per_thread`,
// which are then appended to `out` in order: the same elements in the same order for any thread
// count.
template <class Element, class Gather>
void gather_in_parallel(Index count, std::vector<std::vector<Element>>& per_thread,
                        std::vector<Element>& out, const Gather& gather) {
  if (count < kMinParallelItems) {
    for (Index i = 0; i < count; ++i) {
      gather(i, out);
    }
    return;
  }
  ThreadTeam& team = thread_team();
  if (per_thread.size() < static_cast<std::size_t>(team.size())) {
    per_thread.resize(static_cast<std::size_t>(team.size()));
  }
  team.run([&](const TeamMember& member) {
    std::vector<Element>& list = per_thread[static_cast<std::size_t>(member.index())];
    list.clear();
    const auto [first, last] = member.share(count);
    for (Index i = first; i < last; ++i) {
      gather(i, list);
    }
  });
  for (int m = 0; m < team.size(); ++m) {
    const std::vector<Element>& list = per_thread[static_cast<std::size_t>(m)];
    out.insert(out.end(), list.begin(), list.end());
  }
}

// The narrowest skin, as a fraction of the widest (the largest contact radius).
constexpr double kNarrowestSkin = 0.05;

// What a search costs, in candidate checks (contact_pairs.hpp).
double search_cost(const ObjectContact& contact) {
  return kSearchCostInChecks * static_cast<double>(contact.bars.size() + contact.points.size());
}

// The candidate checks made since the last search: its candidates, every step since.
double checks_since_search(const State& state) {
  const ObjectContactWorkspace& work = state.object_contact;
  const auto steps = std::max<std::int64_t>(state.step - work.search_step, 1);
  return static_cast<double>(steps) * static_cast<double>(work.candidates.size());
}

// The skin for the next search (contact_pairs.hpp): narrower while checking the candidates since
// the last search cost more than a search, wider while it cost under a quarter of one.
double next_skin(const Model& model, const State& state) {
  const ObjectContact& contact = model.contact;
  const ObjectContactWorkspace& work = state.object_contact;
  if (!work.candidates_found) {
    return contact.skin;
  }
  const double checks = checks_since_search(state);
  const double search = search_cost(contact);
  if (checks > search) {
    return std::max(0.7 * work.skin, kNarrowestSkin * contact.skin);
  }
  if (checks < 0.25 * search) {
    return std::min(1.4 * work.skin, contact.skin);
  }
  return work.skin;
}

// Every pair within reach + 2 skin at the current positions.
void find_candidates(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  ObjectContactWorkspace& work = state.object_contact;
  const std::vector<Vec3>& x = state.x;
  work.skin = next_skin(model, state);
  const double skin = work.skin;
  file_boxes(model, state);
  work.candidates.clear();
  auto search = [&](Index count, const auto& gather) {
    gather_in_parallel(count, work.thread_candidates, work.candidates, gather);
  };
  search(static_cast<Index>(contact.bars.size()), [&](Index k, auto& list) {
    const Index a = contact.bars[k];
    if (work.bar_used[a] == 0) {
      return;
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
      add_if_near(contact, skin, x, {pair_key(kBarBarContact, a, b), {a0, a1, b0, b1}}, list);
    });
  });
  search(static_cast<Index>(contact.points.size()), [&](Index k, auto& list) {
    const Index p = contact.points[k];
    const Box box = box_of(x[p], x[p], contact.point_radius[p] + skin);
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
      add_if_near(contact, skin, x, {pair_key(kPointTriangleContact, p, t), {p, c[0], c[1], c[2]}},
                  list);
    });
  });
  work.reference_x = x;
  work.candidates_found = true;
  work.search_step = state.step;
  ++work.searches;
}

// True once some node of the contact has moved by more than the skin since the search.
bool moved_past_skin(const Model& model, const State& state) {
  const ObjectContactWorkspace& work = state.object_contact;
  const double skin_squared = work.skin * work.skin;
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
  // Search again once a node has moved by the skin, or once checking the candidates has cost
  // more than a search with a narrower skin would (contact_pairs.hpp).
  const bool costly = work.candidates_found && work.skin > kNarrowestSkin * contact.skin &&
                      checks_since_search(state) > search_cost(contact);
  if (!work.candidates_found || costly || moved_past_skin(model, state)) {
    find_candidates(model, state);
  }
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

void prepare_object_contact(const Model& model, State& state) {
  if (!model.contact.enabled) {
    return;
  }
  ObjectContactWorkspace& work = state.object_contact;
  const auto triangles = model.contact.triangle_face.size();
  work.bar_boxes.resize(static_cast<std::size_t>(model.bar_count()));
  work.bar_used.assign(static_cast<std::size_t>(model.bar_count()), 0);
  work.triangle_boxes.resize(triangles);
  work.triangle_used.assign(triangles, 0);
  work.reference_x.resize(static_cast<std::size_t>(model.node_count()));
}

}  // namespace dinam
