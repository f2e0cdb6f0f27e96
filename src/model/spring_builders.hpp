#pragma once
// The builders of the springs that span more than one bar. Each works on one object's range of
// nodes and bars, after its bars exist; adjacency is found from the bars themselves.
#include <span>
#include <utility>
#include <vector>

#include "model/model.hpp"

namespace dinam {

// The material of each bar of an object (ObjectDesc::parts), by the bar's index in the object.
using BarMaterials = std::vector<const MaterialDesc*>;  // (object's n_bars)

// The bars at each node of an object, as (other node, bar id) in increasing bar id, in two flat
// arrays (a list per node would cost a heap block each, which dominated building a
// million-node model).
struct NodeAdjacency {
  using Link = std::pair<Index, Index>;  // (other node, bar id)
  std::vector<Index> offsets;            // (object's n_nodes + 1) into links
  std::vector<Link> links;

  Index node_count() const { return static_cast<Index>(offsets.size()) - 1; }
  // The links of the object's node `local` (its id less the object's first node).
  std::span<const Link> operator[](Index local) const {
    return {links.data() + offsets[local], links.data() + offsets[local + 1]};
  }
};
NodeAdjacency node_adjacency(const Model& model, const ModelObject& object);

// Bending springs between the chosen pairs of bars at each node: the two half-bars' bending
// stiffnesses in series, k = 2 / (L1 / E1I1 + L2 / E2I2), which is 2 E I / (L1 + L2) for one
// material; yield at the weaker bar's moment.
void add_bending_springs(const BarMaterials& materials, BendingPairs pairs,
                         const ModelObject& object, const NodeAdjacency& adjacency, Model& model);

// The faces' corner springs (face_springs.hpp), in node ids, as bending springs: each holds the
// angle at its corner, which shear in the face's plane changes. Elastic.
struct CornerSpring;
void add_corner_springs(const std::vector<CornerSpring>& corners, Model& model);

// At each pinned node of a clamped object (ObjectDesc::pins_clamped), the bending springs centred
// there give way to one clamp per bar to a free node (model.hpp), which holds that bar's rest
// direction; bending springs must already be built.
void add_clamps(const BarMaterials& materials, const ModelObject& object,
                const NodeAdjacency& adjacency, Model& model, Index first_bend);

// One torsion spring k = G J / L0 per bar that has a usable reference neighbour at each end: the
// bar most nearly perpendicular to it, at least kMinReferenceSine away from collinear.
inline constexpr double kMinReferenceSine = 0.2;  // about 11.5°
void add_torsion_springs(const BarMaterials& materials, const ModelObject& object,
                         const NodeAdjacency& adjacency, Model& model);

// Tearing, when some bar's material can break (MaterialDesc::breaking_*): each bar's limits, and
// the springs and faces that stand on it (model.hpp), found from the springs' node ids; every
// spring and face must already be built. `materials` holds each object's BarMaterials.
void add_tearing(const std::vector<BarMaterials>& materials, Model& model);

}  // namespace dinam
