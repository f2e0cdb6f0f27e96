#include "dynamics/object_contact.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_geometry.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

constexpr std::uint64_t kBarBar = 0;
constexpr std::uint64_t kPointTriangle = 1;

std::uint64_t pair_key(std::uint64_t kind, Index a, Index b) {
  return kind << 63 | static_cast<std::uint64_t>(a) << 32 | static_cast<std::uint64_t>(b);
}

Box box_of(const Vec3& a, const Vec3& b, double radius) {
  return {a.cwiseMin(b).array() - radius, a.cwiseMax(b).array() + radius};
}

// The bars' and triangles' boxes at the current positions, and the grids over them.
void update_broad_phase(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  ObjectContactWorkspace& work = state.object_contact;
  const std::vector<Vec3>& x = state.x;
  work.bar_boxes.resize(model.bar_count());
  work.bar_used.assign(model.bar_count(), 0);
  for (const Index b : contact.bars) {
    if (!state.bar_broken.empty() && state.bar_broken[b] != 0) {
      continue;
    }
    work.bar_boxes[b] =
        box_of(x[model.bar_nodes[2 * b]], x[model.bar_nodes[2 * b + 1]], contact.bar_radius[b]);
    work.bar_used[b] = 1;
  }
  const auto triangles = static_cast<Index>(contact.triangle_face.size());
  work.triangle_boxes.resize(triangles);
  work.triangle_used.assign(triangles, 0);
  for (Index t = 0; t < triangles; ++t) {
    if (!state.face_broken.empty() && state.face_broken[contact.triangle_face[t]] != 0) {
      continue;
    }
    const Index* corners = &contact.triangles[3 * t];
    Box box = box_of(x[corners[0]], x[corners[1]], contact.triangle_radius[t]);
    box.min = box.min.cwiseMin(x[corners[2]] - Vec3::Constant(contact.triangle_radius[t]));
    box.max = box.max.cwiseMax(x[corners[2]] + Vec3::Constant(contact.triangle_radius[t]));
    work.triangle_boxes[t] = box;
    work.triangle_used[t] = 1;
  }
  double widest_point = 0.0;
  for (const Index p : contact.points) {
    widest_point = std::max(widest_point, 2.0 * contact.point_radius[p]);
  }
  work.bar_grid.build(work.bar_boxes, work.bar_used, 0.0);
  work.triangle_grid.build(work.triangle_boxes, work.triangle_used, widest_point);
}

bool objects_may_touch(const ObjectContact& contact, Index object_a, Index object_b) {
  return object_a == object_b
             ? contact.object_self[object_a] != 0
             : contact.object_between[object_a] != 0 && contact.object_between[object_b] != 0;
}

// Appends the pair when its closest points are nearer than `reach`.
void add_if_touching(const std::vector<Vec3>& x, std::uint64_t key,
                     const std::array<Index, 4>& nodes, const std::array<double, 4>& weights,
                     double reach, std::vector<ContactPoint>& touching) {
  Vec3 separation = Vec3::Zero();
  for (int j = 0; j < 4; ++j) {
    separation += weights[j] * x[nodes[j]];
  }
  if (separation.squaredNorm() < reach * reach) {
    ContactPoint& point = touching.emplace_back();
    point.key = key;
    point.nodes = nodes;
    point.weights = weights;
    point.separation = separation;
  }
}

// Every touching pair at the current positions, in key order.
void find_touching_pairs(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  ObjectContactWorkspace& work = state.object_contact;
  const std::vector<Vec3>& x = state.x;
  work.touching.clear();
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
          (!a_free && model.pinned(b0) && model.pinned(b1))) {
        return;
      }
      const SegmentPair closest = closest_points_of_segments(x[a0], x[a1], x[b0], x[b1]);
      add_if_touching(x, pair_key(kBarBar, a, b), {a0, a1, b0, b1},
                      {1.0 - closest.s, closest.s, closest.t - 1.0, -closest.t},
                      contact.bar_radius[a] + contact.bar_radius[b], work.touching);
    });
  }
  for (const Index p : contact.points) {
    const Box box = box_of(x[p], x[p], contact.point_radius[p]);
    const Index object_p = model.node_object[p];
    work.triangle_grid.visit_overlapping(box, [&](Index t) {
      const Index* c = &contact.triangles[3 * t];
      if (p == c[0] || p == c[1] || p == c[2] ||
          !objects_may_touch(contact, object_p, model.node_object[c[0]]) ||
          (model.pinned(p) && model.pinned(c[0]) && model.pinned(c[1]) && model.pinned(c[2]))) {
        return;
      }
      const std::array<double, 3> w = closest_point_of_triangle(x[p], x[c[0]], x[c[1]], x[c[2]]);
      add_if_touching(x, pair_key(kPointTriangle, p, t), {p, c[0], c[1], c[2]},
                      {1.0, -w[0], -w[1], -w[2]},
                      contact.point_radius[p] + contact.triangle_radius[t], work.touching);
    });
  }
  std::sort(work.touching.begin(), work.touching.end(),
            [](const ContactPoint& a, const ContactPoint& b) { return a.key < b.key; });
}

// The direction to push A along when the closest points coincide: across both bars, or along
// the triangle's normal.
Vec3 fallback_normal(const ContactPoint& point, const std::vector<Vec3>& x) {
  const std::array<Index, 4>& n = point.nodes;
  const Vec3 normal = (point.key >> 63) == kBarBar
                          ? Vec3((x[n[1]] - x[n[0]]).cross(x[n[3]] - x[n[2]]))
                          : Vec3((x[n[2]] - x[n[1]]).cross(x[n[3]] - x[n[1]]));
  return normal.squaredNorm() > 0.0 ? normal.normalized() : kWorldUp;
}

}  // namespace

void add_object_contact_forces(ForceContext& context, std::vector<Vec3>* damping_ledger,
                               std::vector<Vec3>* friction_ledger) {
  const Model& model = context.model;
  const ObjectContact& contact = model.contact;
  if (!contact.enabled) {
    return;
  }
  State& state = context.state;
  ObjectContactWorkspace& work = state.object_contact;
  update_broad_phase(model, state);
  find_touching_pairs(model, state);

  work.energy = 0.0;
  auto previous = work.previous.begin();
  for (ContactPoint& point : work.touching) {
    while (previous != work.previous.end() && previous->key < point.key) {
      ++previous;
    }
    const bool touched_before = previous != work.previous.end() && previous->key == point.key;
    const bool bar_pair = (point.key >> 63) == kBarBar;
    const int side_a_nodes = bar_pair ? 2 : 1;  // the nodes before are A's, the rest B's
    // The lightest free node on each side sets the pair's stiffness (see the header).
    // The damper acts on the mass the contact point moves, m = 1 / Σ w_j²/m_j.
    double inverse_a = 0.0;
    double inverse_b = 0.0;
    double inverse_moved = 0.0;
    Vec3 relative_velocity = Vec3::Zero();
    for (int j = 0; j < 4; ++j) {
      const double inverse_mass = model.node_inv_mass[point.nodes[j]];
      double& inverse = j < side_a_nodes ? inverse_a : inverse_b;
      inverse = std::max(inverse, inverse_mass);
      inverse_moved += point.weights[j] * point.weights[j] * inverse_mass;
      relative_velocity += point.weights[j] * state.v_half[point.nodes[j]];
    }
    const double k = contact.omega_squared > 0.0 ? contact.omega_squared / (inverse_a + inverse_b)
                                                 : contact.stiffness;
    const double c =
        inverse_moved > 0.0 ? 2.0 * contact.damping_ratio * std::sqrt(k / inverse_moved) : 0.0;

    const double distance = point.separation.norm();
    const auto side_a = static_cast<Index>((point.key >> 32) & 0x7FFFFFFF);
    const auto side_b = static_cast<Index>(point.key & 0xFFFFFFFF);
    const double reach = bar_pair ? contact.bar_radius[side_a] + contact.bar_radius[side_b]
                                  : contact.point_radius[side_a] + contact.triangle_radius[side_b];
    const Vec3 normal = distance > 1e-12 * reach ? Vec3(point.separation / distance)
                                                 : fallback_normal(point, state.x);
    const double penetration = reach - distance;
    const double elastic = k * penetration;
    const double normal_force = std::max(0.0, elastic - c * relative_velocity.dot(normal));
    point.energy = 0.5 * elastic * penetration;
    work.energy += point.energy;

    // Friction: the stick spring stretches with the relative tangential motion since the pair
    // touched, kept in the current tangent plane.
    const Vec3 tangential_velocity = relative_velocity - relative_velocity.dot(normal) * normal;
    Vec3 slip = touched_before ? previous->slip : Vec3::Zero();
    slip += work.dt * tangential_velocity;
    slip -= slip.dot(normal) * normal;
    const Vec3 trial = -k * slip - c * tangential_velocity;
    const double trial_norm = trial.norm();
    const bool was_sliding = touched_before && previous->sliding;
    const double limit =
        (was_sliding ? contact.kinetic_friction : contact.static_friction) * normal_force;
    Vec3 friction = trial;
    point.sliding = false;
    if (trial_norm > limit) {
      friction = (contact.kinetic_friction * normal_force / trial_norm) * trial;
      slip = -friction / k;
      // A pair that touches without pressing (N = 0) holds nothing, but does not slide either:
      // the next step, pressing, it sticks up to μs N again.
      point.sliding = normal_force > 0.0;
    }
    point.slip = slip;

    const Vec3 damping = (normal_force - elastic) * normal;
    const Vec3 on_a = elastic * normal + damping + friction;
    for (int j = 0; j < 4; ++j) {
      const double w = point.weights[j];
      context.force[point.nodes[j]] += w * on_a;
      if (damping_ledger != nullptr) {
        (*damping_ledger)[point.nodes[j]] += w * damping;
        (*friction_ledger)[point.nodes[j]] += w * friction;
      }
    }
  }
  if (context.update_history) {
    std::swap(work.touching, work.previous);
  }
}

double object_contact_energy(const State& state) {
  return state.object_contact.energy;
}

}  // namespace dinam
