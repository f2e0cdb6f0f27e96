#pragma once
// Unit shapes drawn once per point by instancing: interleaved (position, normal) triangles.
#include <vector>

namespace dinam {

struct PrimitiveMesh {
  std::vector<float> vertices;    // (n_vertices × 6) px py pz nx ny nz
  std::vector<unsigned> indices;  // (n_triangles × 3)
};

// Radius 1 around the origin, a UV sphere.
PrimitiveMesh make_unit_sphere(int slices, int stacks);

}  // namespace dinam
