#include "scene/mesh_generators.hpp"

#include "core/error.hpp"

namespace dinam {

RawMesh make_grid(const GridSpec& spec) {
  DINAM_CHECK(spec.columns >= 1 && spec.rows >= 1);
  RawMesh mesh;
  const int nx = spec.columns + 1;
  for (int row = 0; row <= spec.rows; ++row) {
    for (int column = 0; column <= spec.columns; ++column) {
      mesh.vertices.emplace_back(spec.width * column / spec.columns, spec.height * row / spec.rows,
                                 0.0);
      // u along x; v from the top (row = rows) down, as a picture is laid on the grid.
      mesh.uvs.emplace_back(static_cast<double>(column) / spec.columns,
                            1.0 - static_cast<double>(row) / spec.rows);
    }
  }
  for (int row = 0; row < spec.rows; ++row) {
    for (int column = 0; column < spec.columns; ++column) {
      const Index a = row * nx + column;  // corners counter-clockwise seen from +z
      const Index b = a + 1;
      const Index c = a + nx + 1;
      const Index d = a + nx;
      switch (spec.diagonals) {
        case GridDiagonals::kNone:
          mesh.faces.push_back({a, b, c, d});
          break;
        case GridDiagonals::kOne:
          mesh.faces.push_back({a, b, c});
          mesh.faces.push_back({a, c, d});
          break;
        case GridDiagonals::kBoth:
          mesh.faces.push_back({a, b, c, d});
          mesh.lines.push_back({a, c});
          mesh.lines.push_back({b, d});
          break;
      }
    }
  }
  return mesh;
}

RawMesh make_polyline(const PolylineSpec& spec) {
  DINAM_CHECK(spec.points.size() >= 2 && spec.segments_per_span >= 1);
  RawMesh mesh;
  std::vector<Index> chain;
  mesh.vertices.push_back(spec.points.front());
  chain.push_back(0);
  for (std::size_t span = 0; span + 1 < spec.points.size(); ++span) {
    const Vec3& p0 = spec.points[span];
    const Vec3& p1 = spec.points[span + 1];
    for (int s = 1; s <= spec.segments_per_span; ++s) {
      const double t = static_cast<double>(s) / spec.segments_per_span;
      chain.push_back(static_cast<Index>(mesh.vertices.size()));
      mesh.vertices.push_back((1.0 - t) * p0 + t * p1);
    }
  }
  mesh.lines.push_back(std::move(chain));
  return mesh;
}

}  // namespace dinam
