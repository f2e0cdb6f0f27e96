#pragma once
// The physical model: built once from a scene, then only read (`const Model&`). Everything that
// changes during a run lives in dynamics' State. Arrays are flat and indexed by element id; each
// comment gives the shape and the unit.
#include <string>
#include <vector>

#include "core/types.hpp"

namespace dinam {

// What one scene object became: a contiguous range of nodes and of bars.
struct ModelObject {
  std::string name;
  Index first_node = 0;
  Index node_count = 0;
  Index first_bar = 0;
  Index bar_count = 0;
  double wire_radius = 0.0;   // m; 0 when the section was given by its area
  double section_area = 0.0;  // m²
  Vec3f color{0.8f, 0.8f, 0.8f};
  double render_radius = 0.0;  // m; 0 means "choose from the wire radius and the scene size"
};

struct Model {
  // Nodes: point masses without rotational inertia.
  std::vector<Vec3> node_initial_x;   // (n_nodes) m
  std::vector<Vec3> node_initial_v;   // (n_nodes) m/s
  std::vector<double> node_mass;      // (n_nodes) kg; half of every incident bar's mass
  std::vector<double> node_inv_mass;  // (n_nodes) 1/kg; 0 for pinned nodes, which never move
  std::vector<Index> node_object;     // (n_nodes) object id

  // Bars: one per unique mesh edge, an axial spring k = EA/L0 between nodes n0 and n1.
  std::vector<Index> bar_nodes;             // (n_bars × 2) n0, n1
  std::vector<double> bar_rest_length;      // (n_bars) m
  std::vector<double> bar_axial_stiffness;  // (n_bars) N/m, EA / L0

  // Mesh faces as loops of node ids (for drawing surfaces and for wind later):
  // face k has nodes face_nodes[face_offsets[k] .. face_offsets[k + 1]).
  std::vector<Index> face_offsets;  // (n_faces + 1)
  std::vector<Index> face_nodes;    // (sum of face sizes)

  std::vector<ModelObject> objects;
  Vec3 gravity = Vec3::Zero();  // m/s²

  Index node_count() const { return static_cast<Index>(node_mass.size()); }
  Index bar_count() const { return static_cast<Index>(bar_rest_length.size()); }
  Index face_count() const { return static_cast<Index>(face_offsets.size()) - 1; }
  bool pinned(Index node) const { return node_inv_mass[node] == 0.0; }
  double total_mass() const;
};

struct SceneDescription;

// Builds the model: welds coincident vertices of each object, turns every unique edge into a bar
// and lumps the bar masses onto the nodes. Throws UserError for a zero-length bar or a pinned
// vertex that is on no edge, naming the object and its mesh key.
Model build_model(const SceneDescription& scene);

}  // namespace dinam
