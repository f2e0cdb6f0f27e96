#include <algorithm>
#include <numbers>

#include "core/geometry.hpp"
#include "model/bar_lookup.hpp"
#include "model/face_springs.hpp"
#include "model/frequency_bound.hpp"
#include "model/model_spring_kinds.hpp"
#include "model/spring_builders.hpp"

namespace dinam {
namespace {

// Rest angles closer to straight than this (rad) are rounding, not a bend: a mesh written to six
// decimals (as Blender writes OBJ) holds a 1 cm bar's ends to 5e-7 m, 5e-5 rad; and no real wire
// is built bent by a hundredth of a millimetre per metre.
constexpr double kStraightRounding = 1e-4;

}  // namespace

NodeAdjacency node_adjacency(const Model& model, const ModelObject& object) {
  NodeAdjacency adjacency;
  adjacency.offsets.assign(static_cast<std::size_t>(object.node_count) + 1, 0);
  const Index last_bar = object.first_bar + object.bar_count;
  for (Index b = object.first_bar; b < last_bar; ++b) {
    ++adjacency.offsets[model.bar_nodes[2 * b] - object.first_node + 1];
    ++adjacency.offsets[model.bar_nodes[2 * b + 1] - object.first_node + 1];
  }
  for (Index local = 0; local < object.node_count; ++local) {
    adjacency.offsets[local + 1] += adjacency.offsets[local];
  }
  adjacency.links.resize(static_cast<std::size_t>(adjacency.offsets.back()));
  std::vector<Index> next(adjacency.offsets.begin(), adjacency.offsets.end() - 1);
  for (Index b = object.first_bar; b < last_bar; ++b) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    adjacency.links[next[n0 - object.first_node]++] = {n1, b};
    adjacency.links[next[n1 - object.first_node]++] = {n0, b};
  }
  return adjacency;
}

void add_bending_springs(const BarMaterials& materials, BendingPairs pairs,
                         const ModelObject& object, const NodeAdjacency& adjacency, Model& model) {
  if (pairs == BendingPairs::kNone) {
    return;
  }
  std::vector<std::pair<int, int>> chosen;  // at one node: indices into its bars, first < second
  for (Index local = 0; local < object.node_count; ++local) {
    const Index c = object.first_node + local;
    const auto bars = adjacency[local];
    const Vec3& xc = model.node_initial_x[c];
    chosen.clear();
    // A joint where only wires meet is welded: every pair keeps its angle, or the joint would
    // turn about a member (with three bars in a plane, pairing each with its most collinear
    // partner leaves a T joint free to fold out of the plane). Where a surface's edges meet, each
    // bar pairs with its most collinear partner, so a grid bends like crossing beams and does
    // not resist shear in its plane as a welded grid would.
    const bool on_surface = std::any_of(bars.begin(), bars.end(), [&](const auto& neighbour) {
      return model.bar_on_face[neighbour.second] != 0;
    });
    if (pairs == BendingPairs::kAll || (pairs == BendingPairs::kAuto && !on_surface)) {
      for (int p = 0; p < static_cast<int>(bars.size()); ++p) {
        for (int q = p + 1; q < static_cast<int>(bars.size()); ++q) {
          chosen.emplace_back(p, q);
        }
      }
    } else {
      // Each bar with the partner that makes the widest angle with it (closest to straight).
      for (int p = 0; p < static_cast<int>(bars.size()); ++p) {
        int best = -1;
        double widest = -1.0;
        for (int q = 0; q < static_cast<int>(bars.size()); ++q) {
          if (q == p || materials[bars[q].second - object.first_bar]->area_moment == 0.0) {
            continue;  // a bar that does not bend (a sheet's shared side) is no one's partner
          }
          const double angle = bend_angle(model.node_initial_x[bars[p].first], xc,
                                          model.node_initial_x[bars[q].first]);
          if (angle > widest) {
            widest = angle;
            best = q;
          }
        }
        if (best >= 0) {
          chosen.emplace_back(std::min(p, best), std::max(p, best));
        }
      }
      std::sort(chosen.begin(), chosen.end());
      chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
    }
    for (const auto& [p, q] : chosen) {
      const Index a = bars[p].first;
      const Index b = bars[q].first;
      const double l1 = model.bar_rest_length[bars[p].second];
      const double l2 = model.bar_rest_length[bars[q].second];
      const MaterialDesc& m1 = *materials[bars[p].second - object.first_bar];
      const MaterialDesc& m2 = *materials[bars[q].second - object.first_bar];
      if (m1.area_moment == 0.0 || m2.area_moment == 0.0) {
        continue;  // the shared side of a sheet's two triangles (face_springs.hpp) does not bend
      }
      model.bend_nodes.insert(model.bend_nodes.end(), {a, c, b});
      // A rest angle within 1e-4 rad of straight is rounding in the mesh's coordinates: it is
      // made straight, so that the spring's energy is smooth and least there (a bent rest has its
      // least energy on a cone of directions around straight; see bending_spring.hpp).
      const double rest = bend_angle(model.node_initial_x[a], xc, model.node_initial_x[b]);
      model.bend_rest_angle.push_back(std::numbers::pi - rest < kStraightRounding ? std::numbers::pi
                                                                                  : rest);
      // A beam's bending energy ∫ EI κ²/2 over the length (L1 + L2)/2 that the node stands for,
      // with κ ≈ Δθ / ((L1 + L2)/2), is ½ k Δθ² with k = 2 EI / (L1 + L2); with two materials
      // the two half-bars turn through the same Δθ as rotational springs in series.
      // (The one-material form is kept as it was written, so that its rounding is unchanged.)
      const double ei1 = m1.youngs_modulus * m1.area_moment;
      const double ei2 = m2.youngs_modulus * m2.area_moment;
      model.bend_stiffness.push_back(&m1 == &m2 ? 2.0 * ei1 / (l1 + l2)
                                                : 2.0 / (l1 / ei1 + l2 / ei2));
      model.bend_yield_moment.push_back(std::min(m1.yield_bending_moment, m2.yield_bending_moment));
    }
  }
}

void add_corner_springs(const std::vector<CornerSpring>& corners, Model& model) {
  for (const CornerSpring& corner : corners) {
    model.bend_nodes.insert(model.bend_nodes.end(), {corner.a, corner.c, corner.b});
    model.bend_rest_angle.push_back(bend_angle(model.node_initial_x[corner.a],
                                               model.node_initial_x[corner.c],
                                               model.node_initial_x[corner.b]));
    model.bend_stiffness.push_back(corner.stiffness);
    model.bend_yield_moment.push_back(kNoYield);
  }
}

namespace {

// |∂θ/∂x_a| = 1/L1, |∂θ/∂x_b| = 1/L2, |∂θ/∂x_c| ≤ 1/L1 + 1/L2.
void add_bending_frequency_terms(const Model& model, GershgorinSums& sums) {
  const auto& x = model.node_initial_x;
  for (Index s = 0; s < model.bend_count(); ++s) {
    const Index* nodes = &model.bend_nodes[3 * s];
    const double l1 = (x[nodes[0]] - x[nodes[1]]).norm();
    const double l2 = (x[nodes[2]] - x[nodes[1]]).norm();
    const double norms[3] = {1.0 / l1, 1.0 / l1 + 1.0 / l2, 1.0 / l2};
    sums.add(model, model.bend_stiffness[s], nodes, norms, 3);
  }
}

// A bending spring stands on its two bars.
void add_bars_under_bends(const Model& model, const BarLookup& lookup,
                          std::vector<BarSpring>& stood_on) {
  for (Index s = 0; s < model.bend_count(); ++s) {
    const Index* n = &model.bend_nodes[3 * s];
    stood_on.emplace_back(lookup.find(n[0], n[1]), s);
    stood_on.emplace_back(lookup.find(n[1], n[2]), s);
  }
}

}  // namespace

const ModelSpringKind kBendingSpringModel{
    .name = "bending springs",
    .count = [](const Model& model) { return model.bend_count(); },
    .stiffness = &Model::bend_stiffness,
    .yield_limit = &Model::bend_yield_moment,
    .yields = &Model::bends_yield,
    .add_frequency_terms = add_bending_frequency_terms,
    .add_bars_stood_on = add_bars_under_bends,
    .torn_code = kTornBend,
};

}  // namespace dinam
