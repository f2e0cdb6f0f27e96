#include "dynamics/contact/object_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/closest_points.hpp"
#include "dynamics/contact/contact_candidates.hpp"
#include "dynamics/contact/contact_grid.hpp"
#include "dynamics/contact/contact_pairs.hpp"
#include "dynamics/force_kinds.hpp"
#include "estimate/measured_costs.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// The direction to push A along when the closest points coincide: across both bars, or along
// the triangle's normal.
Vec3 fallback_normal(const ContactPoint& point, const std::vector<Vec3>& x) {
  const std::array<Index, 4>& n = point.nodes;
  const Vec3 normal = (point.key >> 63) == kBarBarContact
                          ? Vec3((x[n[1]] - x[n[0]]).cross(x[n[3]] - x[n[2]]))
                          : Vec3((x[n[2]] - x[n[1]]).cross(x[n[3]] - x[n[1]]));
  return normal.squaredNorm() > 0.0 ? normal.normalized() : kWorldUp;
}

// The side of its triangle's plane that a node–triangle pair's node was on a step before,
// x − Δt v_{n−½} for each of the four nodes (the positions the step came from); +1 where it is
// in the plane, or where no step has been taken.
std::int8_t side_came_from(const ContactPoint& point, const State& state, double dt) {
  std::array<Vec3, 4> before;
  for (int j = 0; j < 4; ++j) {
    before[j] = state.x[point.nodes[j]] - dt * state.velocity[point.nodes[j]];
  }
  return triangle_side(before);
}

// The lightest free node on each side: the largest inverse masses of side A's nodes and side B's.
std::pair<double, double> lightest_inverse_masses(const Model& model, const ContactPoint& point) {
  const int side_a_nodes = (point.key >> 63) == kBarBarContact ? 2 : 1;  // then B's
  double inverse_a = 0.0;
  double inverse_b = 0.0;
  for (int j = 0; j < 4; ++j) {
    double& inverse = j < side_a_nodes ? inverse_a : inverse_b;
    inverse = std::max(inverse, model.node_inv_mass[point.nodes[j]]);
  }
  return {inverse_a, inverse_b};
}

// The automatic penalty is soft near the surface and stiff deeper in. A contact that stays within
// the soft layer (half the reach) oscillates four times slower than the stiff one: an impact
// lasts some 20 automatic steps, so its rebound keeps the spring–dashpot's restitution; a fast
// one that goes deeper meets the full stiffness, which keeps the speed envelope (the header).
// The damper and the friction's stick spring take the soft stiffness. A given `stiffness` is
// linear.
constexpr double kSoftLayerShare = 0.5;             // of the reach
constexpr double kSoftStiffnessShare = 1.0 / 16.0;  // of the stiff penalty's

template <class T>
T penalty_force(T penetration, double soft, double stiff, double knee) {
  return penetration <= knee ? T(soft * penetration)
                             : T(soft * knee + stiff * (penetration - knee));
}

// `reach`: the pair's, contact_reach's.
ContactPenalty contact_penalty(const Model& model, const ContactPoint& point, double reach) {
  if (model.contact.omega_squared <= 0.0) {
    return contact_penalty_between(model, 0.0, 0.0, reach);
  }
  const auto [inverse_a, inverse_b] = lightest_inverse_masses(model, point);
  return contact_penalty_between(model, inverse_a, inverse_b, reach);
}

}  // namespace

double ContactPenalty::force(double penetration) const {
  return penalty_force(penetration, soft, stiff, knee);
}

double ContactPenalty::energy(double penetration) const {
  if (penetration <= knee) {
    return 0.5 * soft * penetration * penetration;
  }
  const double beyond = penetration - knee;
  return soft * knee * (0.5 * knee + beyond) + 0.5 * stiff * beyond * beyond;
}

double ContactPenalty::slope(double penetration) const {
  return penetration <= knee ? soft : stiff;
}

ContactPenalty contact_penalty_between(const Model& model, double inverse_a, double inverse_b,
                                       double reach) {
  const ObjectContact& contact = model.contact;
  if (contact.omega_squared <= 0.0) {
    return {contact.stiffness, contact.stiffness, std::numeric_limits<double>::infinity()};
  }
  const double stiff = contact.omega_squared / (inverse_a + inverse_b);
  return {kSoftStiffnessShare * stiff, stiff, kSoftLayerShare * reach};
}

std::int8_t triangle_side(const std::array<Vec3, 4>& at) {
  const Vec3 face = (at[2] - at[1]).cross(at[3] - at[1]);
  return (at[0] - at[1]).dot(face) < 0.0 ? std::int8_t{-1} : std::int8_t{1};
}

ContactPush contact_push(const Model& model, const ContactPoint& point,
                         const std::vector<Vec3>& x) {
  const double reach = contact_reach(model.contact, point.key);
  const ContactPenalty penalty = contact_penalty(model, point, reach);
  ContactPush push;
  push.penalty = penalty;
  push.soft_stiffness = penalty.soft;
  const double distance = point.separation.norm();
  push.normal =
      distance > 1e-12 * reach ? Vec3(point.separation / distance) : fallback_normal(point, x);
  push.penetration = reach - distance;
  if ((point.key >> 63) != kBarBarContact) {
    const std::array<Index, 4>& n = point.nodes;
    const Vec3 face = (x[n[2]] - x[n[1]]).cross(x[n[3]] - x[n[1]]);
    if (point.separation.dot(face) * point.side < 0.0) {
      push.normal = point.side * fallback_normal(point, x);  // the triangle's unit normal
      push.penetration = reach + distance;
    }
  }
  push.force = penalty.force(push.penetration);
  push.energy = penalty.energy(push.penetration);
  return push;
}

void add_object_contact_forces(ForceContext& context, std::vector<Vec3>* damping_ledger,
                               std::vector<Vec3>* friction_ledger) {
  const Model& model = context.model;
  const ObjectContact& contact = model.contact;
  if (!contact.enabled) {
    return;
  }
  State& state = context.state;
  ObjectContactWorkspace& work = state.object_contact;
  const double dt = state.dt;
  find_touching_pairs(model, state);

  work.energy = 0.0;
  auto previous = work.previous.begin();
  for (ContactPoint& point : work.touching) {
    while (previous != work.previous.end() && previous->features < point.features) {
      ++previous;
    }
    const bool touched_before =
        previous != work.previous.end() && previous->features == point.features;
    // The damper acts on the mass the contact point moves, m = 1 / Σ w_j²/m_j, and on the relative
    // velocity at t_n: v_{n−½} plus what the forces added so far on its nodes bring about by then
    // (the team's, and the pairs' before it), its own push solved for, as at the ground
    // (ground_contact.hpp); and in the step a pair first touches, only for its share of that step.
    double inverse_moved = 0.0;
    Vec3 relative_velocity = Vec3::Zero();
    Vec3 predicted_velocity = Vec3::Zero();
    for (int j = 0; j < 4; ++j) {
      const Index node = point.nodes[j];
      const double inverse_mass = model.node_inv_mass[node];
      inverse_moved += point.weights[j] * point.weights[j] * inverse_mass;
      relative_velocity += point.weights[j] * state.velocity[node];
      predicted_velocity += point.weights[j] * (0.5 * dt * inverse_mass) * context.force[node];
    }
    predicted_velocity += relative_velocity;
    if ((point.key >> 63) != kBarBarContact) {
      // A node against a triangle is pushed back to the side it came from, even where it has
      // crossed the triangle's middle within a step (beyond the speed envelope), instead of on
      // through: the side where it first touched, or, if it crossed in that very step, the side
      // it was on a step before.
      point.side = touched_before ? previous->side : side_came_from(point, state, dt);
    }
    const ContactPush push = contact_push(model, point, state.x);
    const Vec3& normal = push.normal;
    const double penetration = push.penetration;
    const double k = push.soft_stiffness;
    double c =
        inverse_moved > 0.0 ? 2.0 * contact.damping_ratio * std::sqrt(k / inverse_moved) : 0.0;
    const double approach = -relative_velocity.dot(normal);
    if (!touched_before && dt > 0.0 && penetration < approach * dt) {
      c *= (penetration / approach + 0.5 * dt) / dt;
    }
    const double elastic = push.force;
    const double normal_force = std::max(
        0.0, (elastic - c * predicted_velocity.dot(normal)) / (1.0 + 0.5 * dt * c * inverse_moved));
    point.energy = push.energy;
    work.energy += point.energy;

    // Friction: the stick spring stretches with the relative tangential motion since the pair
    // touched, kept in the current tangent plane.
    const Vec3 tangential_velocity = relative_velocity - relative_velocity.dot(normal) * normal;
    Vec3 slip = touched_before ? previous->slip : Vec3::Zero();
    slip += dt * tangential_velocity;
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

void add_object_contact_stiffness(const Model& model, const State& state, StiffnessSink& sink) {
  if (!model.contact.enabled) {
    return;
  }
  for (const ContactPoint& point : state.object_contact.touching) {
    const double reach = contact_reach(model.contact, point.key);
    const ContactPenalty penalty = contact_penalty(model, point, reach);
    const bool bar_pair = (point.key >> 63) == kBarBarContact;
    std::array<Vec3, 4> at;
    for (int j = 0; j < 4; ++j) {
      at[j] = state.x[point.nodes[j]];
    }
    // k (reach − |s|) s/|s| at the closest points, s = Σ w_j x_j their separation, shared out by
    // the weights, which move with the nodes. Where the points coincide the direction is lost;
    // the penalty there pushes along a fallback normal whose stiffness is left out.
    const LocalStiffness<4> stiffness = local_stiffness<4>(at, [&](const auto& x) {
      using V = std::decay_t<decltype(x[0])>;
      using T = typename V::Scalar;
      std::array<T, 4> w;
      if (bar_pair) {
        const SegmentPairOf<T> c = closest_points_of_segments(x[0], x[1], x[2], x[3]);
        w = {T(1.0) - c.s, c.s, c.t - 1.0, -c.t};
      } else {
        const std::array<T, 3> c = closest_point_of_triangle(x[0], x[1], x[2], x[3]);
        w = {T(1.0), -c[0], -c[1], -c[2]};
      }
      V separation = V::Zero();
      for (int j = 0; j < 4; ++j) {
        separation += w[j] * x[j];
      }
      using std::sqrt;
      const T distance = sqrt(separation.squaredNorm());
      const T scale =
          distance > 1e-12 * reach
              ? T(penalty_force<T>(reach - distance, penalty.soft, penalty.stiff, penalty.knee) /
                  distance)
              : T(0.0);
      const V on_a = scale * separation;
      return std::array<V, 4>{w[0] * on_a, w[1] * on_a, w[2] * on_a, w[3] * on_a};
    });
    sink.add(point.nodes.data(), 4, stiffness.data());
  }
}

namespace {

// The bars and nodes of contact that belong to a surface in contact with itself (an object with
// self-contact and triangles, not all of it pinned), and the others.
std::pair<double, double> pressed_and_watched(const Model& model) {
  const ObjectContact& contact = model.contact;
  std::vector<std::uint8_t> folds(contact.object_self.size(), 0);
  for (std::size_t t = 0; t < contact.triangle_face.size(); ++t) {
    const Index* corners = &contact.triangles[3 * t];
    const Index object = model.node_object[corners[0]];
    if (contact.object_self[object] != 0 &&
        !(model.pinned(corners[0]) && model.pinned(corners[1]) && model.pinned(corners[2]))) {
      folds[object] = 1;
    }
  }
  double pressed = 0.0;
  for (const Index b : contact.bars) {
    pressed += folds[model.node_object[model.bar_nodes[2 * b]]];
  }
  for (const Index p : contact.points) {
    pressed += folds[model.node_object[p]];
  }
  const auto all = static_cast<double>(contact.bars.size() + contact.points.size());
  return {pressed, all - pressed};
}

}  // namespace

// Contact between objects and within one: found after the team's job (its pair search shares
// its own loops), its penalty's energy booked where the pairs touch at the last force evaluation.
// Under the implicit step its penalty and lagged friction are
// dynamics/contact/object_contact_implicit.hpp's.
const ForceKind kObjectContact{
    .label = "contact between objects",
    .spring = nullptr,
    .role = ForceRole::kContact,
    .implicit = ImplicitTreatment::kOwnContact,
    .damper = {},
    .switched = &ForceSwitches::object_contact,
    .present = [](const Model& model) { return model.contact.enabled; },
    .prepare_forces = nullptr,
    .add_forces = nullptr,
    .add_forces_after_team =
        [](ForceContext& total) {
          add_object_contact_forces(total,
                                    ledger_part(total.state, &EnergyWorkspace::contact_damping),
                                    ledger_part(total.state, &EnergyWorkspace::friction));
        },
    .add_potential = nullptr,  // not of the positions alone: of the pairs the last evaluation found
    .add_stiffness = add_object_contact_stiffness,
    .report_energy = [](const Model&, const State& state,
                        EnergyReport& report) { report.contact += object_contact_energy(state); },
    .ledger = {{&EnergyWorkspace::contact_damping, &EnergyAccounts::contact_damping_work},
               {&EnergyWorkspace::friction, &EnergyAccounts::friction_work}},
    // A box and a flag per bar and triangle, a reference per node.
    .prepare_state = prepare_object_contact,
    .state_bytes = [](const Model& model, bool) -> std::uint64_t {
      if (!model.contact.enabled) {
        return 0;
      }
      const std::uint64_t items = model.contact.bars.size() + model.contact.triangle_face.size();
      return items * (sizeof(Box) + sizeof(std::uint8_t)) +
             static_cast<std::uint64_t>(model.node_count()) * sizeof(Vec3) +
             model.objects.size() * sizeof(std::uint8_t);  // which objects' bars look for pairs
    },
    .add_cost =
        [](const Model& model, StepCostSink& sink) {
          if (model.contact.enabled) {
            const auto [pressed, watched] = pressed_and_watched(model);
            sink.add("contact between objects", watched, measured::kNsPerWatched);
            sink.add_unshared("a surface's contact with itself", pressed, measured::kNsPerPressed);
          }
        },
    .constraint = {},
};

}  // namespace dinam
