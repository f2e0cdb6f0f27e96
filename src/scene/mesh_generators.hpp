#pragma once
// Built-in meshes, so that a cloth or a rope needs no file. Both are made in object space and
// placed by the object's Transform like any loaded mesh.
#include <vector>

#include "scene/raw_mesh.hpp"

namespace dinam {

enum class GridDiagonals { kNone, kOne, kBoth };

// A width × height rectangle in the object's x-y plane, corner at the origin, divided into
// columns × rows cells. Vertex id = row * (columns + 1) + column, row 0 at y = 0.
// kNone gives quad faces, kOne splits each quad into two triangles, kBoth keeps the quads and
// adds both diagonals of every cell as lines (cross bracing that resists shear symmetrically).
struct GridSpec {
  double width = 1.0;   // m, along x
  double height = 1.0;  // m, along y
  int columns = 10;
  int rows = 10;
  GridDiagonals diagonals = GridDiagonals::kOne;
};

RawMesh make_grid(const GridSpec& spec);

// A chain through the given points, each span divided into `segments_per_span` equal bars.
struct PolylineSpec {
  std::vector<Vec3> points;  // m, at least two
  int segments_per_span = 1;
};

RawMesh make_polyline(const PolylineSpec& spec);

}  // namespace dinam
