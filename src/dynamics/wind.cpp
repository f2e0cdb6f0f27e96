#include "dynamics/wind.hpp"

#include <cmath>

#include "core/geometry.hpp"
#include "dynamics/broken.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/vector_lanes.hpp"
#include "dynamics/wind_field.hpp"
#include "estimate/measured_costs.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// Faces, bars and nodes go through the loops below in blocks of this many: each block is gathered
// into arrays by coordinate, computed one item per SIMD lane without branches, then stored.
constexpr Index kWindBlock = 64;

// A block of faces or bars, gathered.
struct DragBlock {
  Vec3Lanes<kWindBlock> shape;     // a face's area vector, a bar's x1 − x0, m² or m
  Vec3Lanes<kWindBlock> velocity;  // its nodes' mean velocity (a face: their sum), m/s
  Vec3Lanes<kWindBlock> wind;      // the wind it feels (a turbulent face: its nodes' sum), m/s
  Vec3Lanes<kWindBlock> force;     // N, on each of its nodes (the output)
  double size[kWindBlock];         // a face's node count; a bar's diameter, m
  double acts[kWindBlock];         // 1, or 0 for a torn face or bar
};

// The wind at every node in the wind, when it is turbulent (uniform otherwise: no node needs it).
void evaluate_node_winds(const TeamMember& member, const WindLoad& wind, const Vec3& uniform,
                         double time, State& state) {
  const TurbulencePhases phases = turbulence_phases(wind, time);
  const Index count = static_cast<Index>(wind.nodes.size());
  for_each_block_share(member, count, kWindBlock, [&](Index first, Index size) {
    Vec3Lanes<kWindBlock> x = {};  // (zeroed: the compiler cannot see that size > 0)
    Vec3Lanes<kWindBlock> u;
    for (Index k = 0; k < size; ++k) {
      x.set(k, state.x[wind.nodes[first + k]]);
    }
    wind_at_points(wind, phases, uniform, x.coordinate[0], x.coordinate[1], x.coordinate[2], size,
                   u.coordinate[0], u.coordinate[1], u.coordinate[2]);
    for (Index k = 0; k < size; ++k) {
      state.wind.node_wind[wind.nodes[first + k]] = u.get(k);
    }
  });
}

// The drag on each face (shared by its nodes) or bar (half to each end) of a block, one item per
// SIMD lane. As with the springs (spring_block.hpp), `drag` must be a lambda without captures, or
// the loop will not vectorise. GCC vectorises it by itself; `omp simd` would keep it from doing so
// (the Vec3 temporaries, passed by reference, would become per-lane arrays in memory).
template <class Drag>
void compute_drag(DragBlock& block, Index size, const WindDesc& field, double drag_coefficient,
                  const Drag& drag) {
  const double air_density = field.air_density;
  const bool turbulent = field.turbulence != 0.0;
  for (Index k = 0; k < size; ++k) {
    const Vec3 force = drag(block, k, air_density, drag_coefficient, turbulent);
    const bool acts = block.acts[k] != 0.0;
    block.force.coordinate[0][k] = acts ? force.x() : 0.0;
    block.force.coordinate[1][k] = acts ? force.y() : 0.0;
    block.force.coordinate[2][k] = acts ? force.z() : 0.0;
  }
}

void store_forces(const DragBlock& block, Index size, Vec3* out) {
  for (Index k = 0; k < size; ++k) {
    out[k] = block.force.get(k);
  }
}

// The area vector of the face whose nodes are face_nodes[begin, end): its length is the area.
// A triangle's is ½ (x1 − x0) × (x2 − x0); a polygon's, Newell's ½ Σ x_k × x_{k+1}, exact for
// planar polygons and the best plane for warped ones.
Vec3 face_area_vector(const Model& model, const std::vector<Vec3>& x, Index begin, Index end) {
  const Index* ids = &model.face_nodes[begin];
  if (end - begin == 3) {
    const Vec3& origin = x[ids[0]];
    return 0.5 * cross3(x[ids[1]] - origin, x[ids[2]] - origin);
  }
  Vec3 area_vector = Vec3::Zero();
  for (Index j = 0; j < end - begin; ++j) {
    const Index next = j + 1 < end - begin ? j + 1 : 0;
    area_vector += 0.5 * cross3(x[ids[j]], x[ids[next]]);
  }
  return area_vector;
}

void face_forces(const TeamMember& member, const Model& model, const Vec3& uniform, State& state) {
  const WindLoad& wind = model.wind;
  const bool turbulent = wind.field.turbulence != 0.0;
  const Index count = static_cast<Index>(wind.faces.size());
  for_each_block_share(member, count, kWindBlock, [&](Index first, Index size) {
    DragBlock block;
    for (Index k = 0; k < size; ++k) {
      const Index f = wind.faces[first + k];
      const Index begin = model.face_offsets[f];
      const Index end = model.face_offsets[f + 1];
      const double nodes = end - begin;
      Vec3 velocity = Vec3::Zero();
      Vec3 felt = Vec3::Zero();
      for (Index j = begin; j < end; ++j) {
        velocity += state.velocity[model.face_nodes[j]];
      }
      if (turbulent) {
        for (Index j = begin; j < end; ++j) {
          felt += state.wind.node_wind[model.face_nodes[j]];
        }
      }
      const Vec3 area_vector = face_area_vector(model, state.x, begin, end);
      // The sums: the means are taken in the SIMD loop.
      block.shape.set(k, area_vector);
      block.velocity.set(k, velocity);
      block.wind.set(k, turbulent ? felt : uniform);
      block.size[k] = nodes;
      block.acts[k] = is_broken(state.face_broken, f) ? 0.0 : 1.0;  // torn open: the wind passes
    }
    compute_drag(
        block, size, wind.field, wind.field.face_drag,
        [](const DragBlock& faces, Index k, double rho, double drag, bool is_turbulent)
            __attribute__((always_inline)) {
              const double share = 1.0 / faces.size[k];  // of each node
              const Vec3 velocity = share * faces.velocity.get(k);
              const Vec3 wind_sum = faces.wind.get(k);
              const Vec3 felt = is_turbulent ? Vec3(share * wind_sum) : wind_sum;
              return Vec3(share * face_drag(faces.shape.get(k), felt - velocity, rho, drag));
            });
    store_forces(block, size, &state.wind.item_force[first]);
  });
}

void bar_forces(const TeamMember& member, const Model& model, const Vec3& uniform, State& state) {
  const WindLoad& wind = model.wind;
  const bool turbulent = wind.field.turbulence != 0.0;
  const Index count = static_cast<Index>(wind.bars.size());
  Vec3* out = state.wind.item_force.data() + wind.faces.size();  // the bars follow the faces
  for_each_block_share(member, count, kWindBlock, [&](Index first, Index size) {
    DragBlock block;
    for (Index k = 0; k < size; ++k) {
      const Index b = wind.bars[first + k];
      const Index n0 = model.bar_nodes[2 * b];
      const Index n1 = model.bar_nodes[2 * b + 1];
      block.shape.set(k, state.x[n1] - state.x[n0]);
      block.velocity.set(k, 0.5 * (state.velocity[n0] + state.velocity[n1]));
      block.wind.set(k, turbulent
                            ? Vec3(0.5 * (state.wind.node_wind[n0] + state.wind.node_wind[n1]))
                            : uniform);
      block.size[k] = 2.0 * model.bar_radius[b];
      block.acts[k] = is_broken(state.bar_broken, b) ? 0.0 : 1.0;
    }
    compute_drag(
        block, size, wind.field, wind.field.bar_drag,
        [](const DragBlock& bars, Index k, double rho, double drag, bool)
            __attribute__((always_inline)) {
              const Vec3 relative = bars.wind.get(k) - bars.velocity.get(k);
              return Vec3(0.5 * bar_drag(bars.shape.get(k), bars.size[k], relative, rho, drag));
            });
    store_forces(block, size, &out[first]);
  });
}

}  // namespace

void prepare_wind(const Model& model, State& state) {
  const WindLoad& wind = model.wind;
  if (!wind.field.enabled) {
    return;
  }
  state.wind.item_force.assign(wind.faces.size() + wind.bars.size(), Vec3::Zero());
  if (wind.field.turbulence != 0.0) {
    state.wind.node_wind.assign(static_cast<std::size_t>(model.node_count()), Vec3::Zero());
  }
}

void compute_wind_drag(ForceContext& context) {
  const Model& model = context.model;
  const WindLoad& wind = model.wind;
  if (!wind.field.enabled) {
    return;
  }
  State& state = context.state;
  const TeamMember& member = context.worker.member;
  const Vec3 uniform = uniform_wind_velocity(wind.field, context.time);
  if (wind.field.turbulence != 0.0) {
    evaluate_node_winds(member, wind, uniform, context.time, state);
    member.barrier();
  }
  face_forces(member, model, uniform, state);
  bar_forces(member, model, uniform, state);
  member.barrier();
}

void add_wind_forces(ForceContext& context) {
  const Model& model = context.model;
  const WindLoad& wind = model.wind;
  if (!wind.field.enabled) {
    return;
  }
  // Each node adds its faces' drag, then its bars', in ascending order (WindLoad::node_items).
  const std::vector<Vec3>& item_force = context.state.wind.item_force;
  const auto count = static_cast<Index>(wind.nodes.size());
  for (Index k = 0; k < count; ++k) {
    const Index node = wind.nodes[k];
    if (!context.worker.owns(node)) {
      continue;
    }
    for (Index j = wind.node_item_offsets[k]; j < wind.node_item_offsets[k + 1]; ++j) {
      context.add(node, item_force[wind.node_items[j]]);
    }
  }
}

// The wind's drag: a load that depends on the motion, found per face and bar before the nodes'
// totals are cleared, then added node by node.
const ForceKind kWind{
    .label = "wind",
    .spring = nullptr,
    .role = ForceRole::kLoad,
    .implicit = ImplicitTreatment::kLoadAtStart,
    .damper = {},
    .switched = &ForceSwitches::wind,
    .present = [](const Model& model) { return model.wind.field.enabled; },
    .prepare_forces = compute_wind_drag,
    .add_forces =
        [](ForceContext& total, const StepOptions&) {
          ForceContext booked = booked_in(total, &EnergyWorkspace::wind);
          add_wind_forces(booked);
        },
    .add_forces_after_team = nullptr,
    .add_potential = nullptr,
    .add_stiffness = nullptr,
    .report_energy = nullptr,
    .ledger = {{&EnergyWorkspace::wind, &EnergyAccounts::wind_work}},
    // Each face's and bar's drag, and the wind at each node where it is turbulent.
    .prepare_state = prepare_wind,
    .state_bytes = [](const Model& model, bool) -> std::uint64_t {
      if (!model.wind.field.enabled) {
        return 0;
      }
      const bool turbulent = model.wind.field.turbulence != 0.0;
      return (model.wind.faces.size() + model.wind.bars.size()) * sizeof(Vec3) +
             (turbulent ? static_cast<std::uint64_t>(model.node_count()) * sizeof(Vec3) : 0);
    },
    .add_cost =
        [](const Model& model, StepCostSink& sink) {
          if (!model.wind.field.enabled) {
            return;
          }
          const bool turbulent = model.wind.field.turbulence != 0.0;
          sink.add("wind on faces", static_cast<double>(model.wind.faces.size()),
                   turbulent ? measured::kNsPerWindFaceTurbulent : measured::kNsPerWindFace);
          sink.add("wind on bars", static_cast<double>(model.wind.bars.size()),
                   turbulent ? measured::kNsPerWindBarTurbulent : measured::kNsPerWindBar);
        },
    .constraint = {},
};

}  // namespace dinam
