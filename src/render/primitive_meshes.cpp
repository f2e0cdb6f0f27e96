#include "render/primitive_meshes.hpp"

#include <cmath>
#include <numbers>

namespace dinam {

PrimitiveMesh make_unit_sphere(int slices, int stacks) {
  PrimitiveMesh mesh;
  for (int j = 0; j <= stacks; ++j) {
    const float theta =
        std::numbers::pi_v<float> * static_cast<float>(j) / static_cast<float>(stacks);
    for (int i = 0; i <= slices; ++i) {
      const float phi =
          2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(slices);
      const float x = std::sin(theta) * std::cos(phi);
      const float y = std::sin(theta) * std::sin(phi);
      const float z = std::cos(theta);
      mesh.vertices.insert(mesh.vertices.end(), {x, y, z, x, y, z});
    }
  }
  const auto row = static_cast<unsigned>(slices + 1);
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const auto a = static_cast<unsigned>(j) * row + static_cast<unsigned>(i);
      mesh.indices.insert(mesh.indices.end(), {a, a + row, a + 1, a + 1, a + row, a + row + 1});
    }
  }
  return mesh;
}

}  // namespace dinam
