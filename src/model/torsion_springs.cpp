#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/geometry.hpp"
#include "model/bar_lookup.hpp"
#include "model/frequency_bound.hpp"
#include "model/model_spring_kinds.hpp"
#include "model/spring_builders.hpp"

namespace dinam {
namespace {

// The sine of the angle between two directions.
double sine_between(const Vec3& u, const Vec3& v) {
  return u.cross(v).norm() / (u.norm() * v.norm());
}

// The neighbour of `node` most nearly perpendicular to `axis`, at least kMinReferenceSine away
// from it and not `excluded`, or −1; its sine in *sine.
Index best_reference(const Model& model, const NodeAdjacency& adjacency, const ModelObject& object,
                     Index node, const Vec3& axis, Index excluded_bar, Index excluded_node,
                     double* sine) {
  Index best = -1;
  *sine = kMinReferenceSine;
  for (const auto& [other, bar] : adjacency[node - object.first_node]) {
    if (bar == excluded_bar || other == excluded_node) {
      continue;
    }
    const double s = sine_between(model.node_initial_x[other] - model.node_initial_x[node], axis);
    if (s >= *sine) {
      *sine = s;
      best = other;
    }
  }
  return best;
}

// Adds the spring on the axis i–j with references a and b; `stiffness` is G J / L of the bar it
// stands for (or of a straight run's bars in series) and `yield` the weakest one's.
void push_torsion_spring(Model& model, Index a, Index i, Index j, Index b, double stiffness,
                         double yield) {
  const Vec3 axis = model.node_initial_x[j] - model.node_initial_x[i];
  const double sine_a = sine_between(model.node_initial_x[a] - model.node_initial_x[i], axis);
  const double sine_b = sine_between(model.node_initial_x[b] - model.node_initial_x[j], axis);
  model.torsion_nodes.insert(model.torsion_nodes.end(), {a, i, j, b});
  model.torsion_rest_angle.push_back(
      dihedral_angle(model.node_initial_x[a], model.node_initial_x[i], model.node_initial_x[j],
                     model.node_initial_x[b]));
  // Per unit of the weight q_a q_b (torsion_spring.hpp), which is q_a0 q_b0 at rest.
  const double rest_weight = sine_a * sine_a * sine_b * sine_b;
  model.torsion_stiffness.push_back(stiffness / rest_weight);
  model.torsion_yield_moment.push_back(yield);
}

// A straight run: bars end to end through nodes that join exactly two nearly collinear bars
// (no reference there), from end node `first` to end node `last`.
struct StraightRun {
  Index first = -1;
  Index last = -1;
  std::vector<Index> bars;
  bool closed = false;  // a ring turning less than kMinReferenceSine at every node: no ends
};

// The node of `bar` that is not `node`.
Index other_end(const Model& model, Index bar, Index node) {
  return model.bar_nodes[2 * bar] == node ? model.bar_nodes[2 * bar + 1] : model.bar_nodes[2 * bar];
}

// The bar that continues a run through `node` from `bar`, or −1 where the run ends there.
Index continuation(const Model& model, const NodeAdjacency& adjacency, const ModelObject& object,
                   Index node, Index bar) {
  const auto bars = adjacency[node - object.first_node];
  if (bars.size() != 2) {
    return -1;
  }
  const auto& [next_node, next_bar] = bars[0].second == bar ? bars[1] : bars[0];
  const Vec3 in = model.node_initial_x[node] - model.node_initial_x[other_end(model, bar, node)];
  const Vec3 out = model.node_initial_x[next_node] - model.node_initial_x[node];
  return sine_between(in, out) < kMinReferenceSine ? next_bar : -1;
}

StraightRun run_through(const Model& model, const NodeAdjacency& adjacency,
                        const ModelObject& object, Index bar) {
  StraightRun run;
  run.bars.push_back(bar);
  // Walk out from each end of `bar`; the walk towards n1 is reversed so that the bars are in
  // order from `first` to `last`.
  for (int side = 0; side < 2; ++side) {
    Index node = model.bar_nodes[2 * bar + side];
    Index along = bar;
    std::vector<Index> walked;
    for (Index next = continuation(model, adjacency, object, node, along); next >= 0;
         next = continuation(model, adjacency, object, node, along)) {
      if (next == bar) {
        run.closed = true;
        run.bars.insert(run.bars.end(), walked.begin(), walked.end());
        return run;
      }
      walked.push_back(next);
      along = next;
      node = other_end(model, next, node);
    }
    if (side == 0) {
      run.first = node;
      run.bars.insert(run.bars.begin(), walked.rbegin(), walked.rend());
    } else {
      run.last = node;
      run.bars.insert(run.bars.end(), walked.begin(), walked.end());
    }
  }
  return run;
}

}  // namespace

void add_torsion_springs(const BarMaterials& materials, const ModelObject& object,
                         const NodeAdjacency& adjacency, Model& model) {
  auto rigidity_of = [&](Index bar) {  // G J
    const MaterialDesc& material = *materials[bar - object.first_bar];
    return material.shear_modulus * material.polar_moment;
  };
  auto yield_of = [&](Index bar) {
    return materials[bar - object.first_bar]->yield_torsion_moment;
  };
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(object.bar_count), 0);
  for (Index bar = object.first_bar; bar < object.first_bar + object.bar_count; ++bar) {
    if (rigidity_of(bar) == 0.0) {  // the shared side of a sheet's two triangles: no twist
      covered[bar - object.first_bar] = 1;
      continue;
    }
    const Index i = model.bar_nodes[2 * bar];
    const Index j = model.bar_nodes[2 * bar + 1];
    const Vec3 axis = model.node_initial_x[j] - model.node_initial_x[i];
    // The best pair of references (a at i, b at j, a ≠ b): the one whose worse end is most
    // nearly perpendicular to the bar.
    Index best_a = -1;
    Index best_b = -1;
    double best_sine = kMinReferenceSine;
    for (const auto& [a, bar_a] : adjacency[i - object.first_node]) {
      if (bar_a == bar) {
        continue;
      }
      const double sine_a = sine_between(model.node_initial_x[a] - model.node_initial_x[i], axis);
      for (const auto& [b, bar_b] : adjacency[j - object.first_node]) {
        if (bar_b == bar || b == a) {
          continue;
        }
        const double sine_b = sine_between(model.node_initial_x[b] - model.node_initial_x[j], axis);
        const double worse = std::min(sine_a, sine_b);
        if (worse >= best_sine) {
          best_sine = worse;
          best_a = a;
          best_b = b;
        }
      }
    }
    if (best_a >= 0) {
      push_torsion_spring(model, best_a, i, j, best_b,
                          rigidity_of(bar) / model.bar_rest_length[bar], yield_of(bar));
      covered[bar - object.first_bar] = 1;
    }
  }

  // A straight member of a wire mesh, cut into several bars, has no references inside it, so its
  // bars get no spring above; yet it must carry twist from one joint to the other, or the joints
  // turn freely about it (a mechanism). So each straight run of bars without a spring gets one
  // spring over its whole length, on the axis between its end nodes with references at those
  // joints: the bars' torsion stiffnesses in series, G J / ΣL for one material.
  for (Index bar = object.first_bar; bar < object.first_bar + object.bar_count; ++bar) {
    if (covered[bar - object.first_bar] != 0) {
      continue;
    }
    const StraightRun run = run_through(model, adjacency, object, bar);
    double compliance = 0.0;
    double yield = std::numeric_limits<double>::infinity();
    for (const Index b : run.bars) {
      covered[b - object.first_bar] = 1;
      compliance += model.bar_rest_length[b] / rigidity_of(b);
      yield = std::min(yield, yield_of(b));
    }
    if (run.closed) {
      model.bars_without_torsion += static_cast<Index>(run.bars.size());
      continue;
    }
    const Vec3 axis = model.node_initial_x[run.last] - model.node_initial_x[run.first];
    double sine = 0.0;
    const Index a = best_reference(model, adjacency, object, run.first, axis, run.bars.front(),
                                   run.last, &sine);
    const Index b =
        best_reference(model, adjacency, object, run.last, axis, run.bars.back(), a, &sine);
    if (a < 0 || b < 0) {
      model.bars_without_torsion += static_cast<Index>(run.bars.size());
      continue;
    }
    push_torsion_spring(model, a, run.first, run.last, b, 1.0 / compliance, yield);
  }
}

namespace {

// |∂φ/∂x_a| = 1/(|b1| sin θ1), |∂φ/∂x_b| = 1/(|b3| sin θ2), and the axis nodes' blocks are
// combinations of those: |g_i| ≤ (1 + |b1|/|b2|) |g_a| + |b3|/|b2| |g_b|. The spring's stiffness
// in φ is its weight sin²θ1 sin²θ2 times torsion_stiffness.
void add_torsion_frequency_terms(const Model& model, GershgorinSums& sums) {
  const auto& x = model.node_initial_x;
  for (Index s = 0; s < model.torsion_count(); ++s) {
    const Index* nodes = &model.torsion_nodes[4 * s];
    const Vec3 b1 = x[nodes[1]] - x[nodes[0]];
    const Vec3 b2 = x[nodes[2]] - x[nodes[1]];
    const Vec3 b3 = x[nodes[3]] - x[nodes[2]];
    const double ga = b2.norm() / b1.cross(b2).norm();
    const double gb = b2.norm() / b2.cross(b3).norm();
    const double r1 = b1.norm() / b2.norm();
    const double r3 = b3.norm() / b2.norm();
    const double norms[4] = {ga, (1 + r1) * ga + r3 * gb, (1 + r3) * gb + r1 * ga, gb};
    const double weight = b1.cross(b2).squaredNorm() / (b1.squaredNorm() * b2.squaredNorm()) *
                          b2.cross(b3).squaredNorm() / (b3.squaredNorm() * b2.squaredNorm());
    sums.add(model, weight * model.torsion_stiffness[s], nodes, norms, 4);
  }
}

// The bars of the straight run from node i to node j (a torsion spring's axis that is no bar):
// from i, each step takes the bar that heads most nearly towards j.
std::vector<Index> run_bars(const Model& model, const NodeAdjacency& adjacency, Index offset,
                            Index i, Index j) {
  std::vector<Index> bars;
  Index node = i;
  while (node != j && bars.size() <= static_cast<std::size_t>(adjacency.node_count())) {
    Index best_bar = -1;
    Index best_node = -1;
    double best = -std::numeric_limits<double>::infinity();
    const Vec3 towards = (model.node_initial_x[j] - model.node_initial_x[node]).normalized();
    for (const auto& [other, bar] : adjacency[node - offset]) {
      const double along =
          (model.node_initial_x[other] - model.node_initial_x[node]).normalized().dot(towards);
      if (along > best) {
        best = along;
        best_bar = bar;
        best_node = other;
      }
    }
    bars.push_back(best_bar);
    node = best_node;
  }
  return bars;
}

// A torsion spring stands on its two arms and on its axis: a bar, or a straight run of them.
void add_bars_under_torsions(const Model& model, const BarLookup& lookup,
                             std::vector<BarSpring>& stood_on) {
  std::vector<NodeAdjacency> adjacency;
  for (const ModelObject& object : model.objects) {
    adjacency.push_back(node_adjacency(model, object));
  }
  for (Index s = 0; s < model.torsion_count(); ++s) {
    const Index* n = &model.torsion_nodes[4 * s];
    stood_on.emplace_back(lookup.find(n[0], n[1]), s);
    stood_on.emplace_back(lookup.find(n[2], n[3]), s);
    if (const Index axis = lookup.find(n[1], n[2]); axis >= 0) {
      stood_on.emplace_back(axis, s);
    } else {
      const Index object = model.node_object[n[1]];
      for (const Index bar : run_bars(model, adjacency[static_cast<std::size_t>(object)],
                                      model.objects[object].first_node, n[1], n[2])) {
        stood_on.emplace_back(bar, s);
      }
    }
  }
}

}  // namespace

const ModelSpringKind kTorsionSpringModel{
    .name = "torsion springs",
    .count = [](const Model& model) { return model.torsion_count(); },
    .stiffness = &Model::torsion_stiffness,
    .yield_limit = &Model::torsion_yield_moment,
    .yields = &Model::torsions_yield,
    .add_frequency_terms = add_torsion_frequency_terms,
    .add_bars_stood_on = add_bars_under_torsions,
    .torn_code = kTornTorsion,
};

}  // namespace dinam
