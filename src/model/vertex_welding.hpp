#pragma once
// Welding: coincident vertices (closer than a tolerance) become one node, so a triangle soup from
// an STL file, where every triangle repeats its corners, stays one connected structure.
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct WeldResult {
  std::vector<Index> node_of_vertex;  // (n_vertices) the welded id of each input vertex
  std::vector<Vec3> nodes;            // (n_welded) position of the first vertex of each group
};

// Vertices within `tolerance` (m) of an earlier kept vertex join it. Ids follow the first
// occurrence, so a mesh without duplicates keeps its vertex order.
WeldResult weld_vertices(const std::vector<Vec3>& vertices, double tolerance);

// The tolerance used for a mesh: 1e-6 of its bounding-box diagonal (far below any sensible bar
// length, far above the rounding of vertex coordinates written as text).
double weld_tolerance(const std::vector<Vec3>& vertices);

}  // namespace dinam
