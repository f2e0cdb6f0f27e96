#include "dynamics/contact/ground_contact.hpp"

#include <algorithm>

#include "dynamics/force_kinds.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/vector_lanes.hpp"
#include "estimate/measured_costs.hpp"

namespace dinam {

namespace {

// Nodes go through the loop below in blocks of this many: gathered into arrays by coordinate,
// computed one node per SIMD lane, then added to the nodes that touch.
constexpr Index kGroundBlock = 64;

struct GroundBlock {
  // Inputs: each touching node's position, velocity, stick anchor (kept, or the foot of a new
  // touch), whether it slid last step (1 or 0), its penalty's stiffness and damping, and what
  // its damper needs (ground_contact.hpp): v*·n and 1 / (1 + cΔt/2m).
  Vec3Lanes<kGroundBlock> x;
  Vec3Lanes<kGroundBlock> v;
  Vec3Lanes<kGroundBlock> anchor;
  double sliding[kGroundBlock];
  double stiffness[kGroundBlock];
  double damping[kGroundBlock];
  double normal_speed[kGroundBlock];
  double implicit[kGroundBlock];
  // Outputs: ContactForces, by coordinate.
  Vec3Lanes<kGroundBlock> elastic;
  Vec3Lanes<kGroundBlock> normal_damping;
  Vec3Lanes<kGroundBlock> friction;
  Vec3Lanes<kGroundBlock> new_anchor;
  double new_sliding[kGroundBlock];
};

}  // namespace

void add_ground_contact_forces(ForceContext& context, std::vector<Vec3>* damping_ledger,
                               std::vector<Vec3>* friction_ledger) {
  const Model& model = context.model;
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return;
  }
  State& state = context.state;
  const double dt = state.dt;
  for_each_own_node_chunk(
      context.worker, model.node_count(), kGroundBlock, [&](Index first, Index size) {
        // 1. Gather the nodes below the plane, packed; a block above it (the usual case) ends here.
        Index touching[kGroundBlock];
        double distance[kGroundBlock];
        Index count = 0;
        for (Index i = first; i < first + size; ++i) {
          const double d = dot3(state.x[i] - ground.point, ground.normal) - ground.node_radius[i];
          if (d < 0.0 && !model.pinned(i)) {
            distance[count] = d;
            touching[count++] = i;
          } else if (context.update_history) {
            state.contact_touching[i] = 0;
            state.contact_sliding[i] = 0;
          }
        }
        if (count == 0) {
          return;
        }
        GroundBlock block;
        for (Index k = 0; k < count; ++k) {
          const Index i = touching[k];
          // The node meets the plane with its lowest point, x − r n.
          const Vec3 lowest = state.x[i] - ground.node_radius[i] * ground.normal;
          block.x.set(k, lowest);
          block.v.set(k, state.velocity[i]);
          // A node that has just touched is anchored at its foot on the plane.
          block.anchor.set(k, state.contact_touching[i] != 0
                                  ? state.contact_anchor[i]
                                  : Vec3(lowest - distance[k] * ground.normal));
          block.sliding[k] = state.contact_sliding[i] != 0 ? 1.0 : 0.0;
          block.stiffness[k] = ground.node_stiffness[i];
          // The damper: its share of the step a node crosses the plane in, τ + Δt/2 of Δt where
          // it crossed τ = −d / (−v·n) ago (a node found deeper than a step's travel started
          // there); then the velocity at t_n that the other forces bring about.
          const double approach = -dot3(state.velocity[i], ground.normal);
          double damping = ground.node_damping[i];
          if (state.contact_touching[i] == 0 && dt > 0.0 && -distance[k] < approach * dt) {
            damping *= (-distance[k] / approach + 0.5 * dt) / dt;
          }
          const double half_step = 0.5 * dt * model.node_inv_mass[i];
          block.damping[k] = damping;
          block.normal_speed[k] = -approach + half_step * dot3(context.force[i], ground.normal);
          block.implicit[k] = 1.0 / (1.0 + damping * half_step);
        }
        // 2. The contact forces, one node per lane (vectorised by GCC without `omp simd`, which
        // would
        //    put the Vec3 temporaries in per-lane arrays in memory and keep it from vectorising).
        for (Index k = 0; k < count; ++k) {
          const ContactForces f =
              ground_contact(ground, block.stiffness[k], block.damping[k], block.normal_speed[k],
                             block.implicit[k], block.x.get(k), block.v.get(k), block.anchor.get(k),
                             block.sliding[k] != 0.0);
          block.elastic.set(k, f.normal_elastic);
          block.normal_damping.set(k, f.normal_damping);
          block.friction.set(k, f.friction);
          block.new_anchor.set(k, f.anchor);
          block.new_sliding[k] = f.sliding ? 1.0 : 0.0;
        }
        // 3. The elastic push, the normal damping and the friction, in that order; the history.
        for (Index k = 0; k < count; ++k) {
          const Index i = touching[k];
          const Vec3 damping = block.normal_damping.get(k);
          const Vec3 friction = block.friction.get(k);
          context.force[i] += block.elastic.get(k);
          context.force[i] += damping;
          context.force[i] += friction;
          if (damping_ledger != nullptr) {
            (*damping_ledger)[i] += damping;
            (*friction_ledger)[i] += friction;
          }
          if (context.update_history) {
            state.contact_touching[i] = 1;
            state.contact_anchor[i] = block.new_anchor.get(k);
            state.contact_sliding[i] = block.new_sliding[k] != 0.0 ? 1 : 0;
          }
        }
      });
}

void add_ground_penalty_forces(ForceContext& context) {
  const Model& model = context.model;
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return;
  }
  const State& state = context.state;
  for_each_own_node(context.worker, model.node_count(), [&](Index i) {
    const double d = dot3(state.x[i] - ground.point, ground.normal) - ground.node_radius[i];
    if (d < 0.0 && !model.pinned(i)) {
      // As ground_contact() finds it: the depth of the node's lowest point, x − r n.
      const Vec3 lowest = state.x[i] - ground.node_radius[i] * ground.normal;
      const double penetration = -dot3(lowest - ground.point, ground.normal);
      context.force[i] += (ground.node_stiffness[i] * penetration) * ground.normal;
    }
  });
}

double ground_contact_energy(const Model& model, const State& state) {
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return 0.0;
  }
  double energy = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    const double penetration = -ground.clearance(i, state.x[i]);
    if (penetration > 0.0 && !model.pinned(i)) {
      energy += 0.5 * ground.node_stiffness[i] * penetration * penetration;
    }
  }
  return energy;
}

void anchor_nodes_at_rest(const Model& model, State& state) {
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return;
  }
  for (Index i = 0; i < model.node_count(); ++i) {
    const double distance = ground.clearance(i, state.x[i]);
    const bool touching = distance < 0.0 && !model.pinned(i);
    state.contact_touching[i] = touching ? 1 : 0;
    state.contact_sliding[i] = 0;
    state.contact_anchor[i] = touching ? ground.foot(state.x[i]) : Vec3::Zero();
  }
}

void add_ground_contact_stiffness(const Model& model, const State& state, StiffnessSink& sink) {
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return;
  }
  const Mat3 normal_outer = ground.normal * ground.normal.transpose();
  for (Index i = 0; i < model.node_count(); ++i) {
    if (ground.clearance(i, state.x[i]) < 0.0 && !model.pinned(i)) {
      const Mat3 k = ground.node_stiffness[i] * normal_outer;
      sink.add(&i, 1, k.data());
    }
  }
}

// The ground: its normal penalty a potential, its damper and friction booked on their lines.
// Under the implicit step the penalty is a term of the step's potential and the friction the
// stick springs of dynamics/contact/ground_friction_implicit.hpp.
const ForceKind kGroundContact{
    .label = "ground",
    .spring = nullptr,
    .role = ForceRole::kContact,
    .implicit = ImplicitTreatment::kInPotential,
    .damper = {},
    .switched = &ForceSwitches::ground,
    .present = [](const Model& model) { return model.ground.enabled; },
    .prepare_forces = nullptr,
    .add_forces =
        [](ForceContext& total, const StepOptions& options) {
          if (options.elastic_only) {
            add_ground_penalty_forces(total);
            return;
          }
          add_ground_contact_forces(total,
                                    ledger_part(total.state, &EnergyWorkspace::contact_damping),
                                    ledger_part(total.state, &EnergyWorkspace::friction));
        },
    .add_forces_after_team = nullptr,
    .add_potential =
        [](const Model& model, const State& state, const PotentialQuery&, Potential& potential) {
          potential.add(ground_contact_energy(model, state));
        },
    .add_stiffness = add_ground_contact_stiffness,
    .report_energy =
        [](const Model& model, const State& state, EnergyReport& report) {
          report.contact += ground_contact_energy(model, state);
        },
    .ledger = {{&EnergyWorkspace::contact_damping, &EnergyAccounts::contact_damping_work},
               {&EnergyWorkspace::friction, &EnergyAccounts::friction_work}},
    // Each node's friction anchor, and whether it touches and slides: only where there is a
    // ground (an elastic structure in the air carries none; memory is part of speed).
    .prepare_state =
        [](const Model& model, State& state) {
          if (model.ground.enabled) {
            const auto n = static_cast<std::size_t>(model.node_count());
            state.contact_anchor.assign(n, Vec3::Zero());
            state.contact_touching.assign(n, 0);
            state.contact_sliding.assign(n, 0);
          }
        },
    .state_bytes = [](const Model& model, bool) -> std::uint64_t {
      return model.ground.enabled ? static_cast<std::uint64_t>(model.node_count()) *
                                        (sizeof(Vec3) + 2 * sizeof(std::uint8_t))
                                  : 0;
    },
    .add_cost =
        [](const Model& model, StepCostSink& sink) {
          sink.add("ground", model.ground.enabled ? static_cast<double>(model.node_count()) : 0.0,
                   measured::kNsPerGroundNode);
        },
    .constraint = {},
};

}  // namespace dinam
