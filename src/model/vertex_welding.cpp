#include "model/vertex_welding.hpp"

#include <cmath>
#include <unordered_map>

namespace dinam {
namespace {

struct CellKey {
  std::int64_t i, j, k;
  bool operator==(const CellKey&) const = default;
};

struct CellHash {
  std::size_t operator()(const CellKey& c) const {
    // Large odd multipliers spread neighbouring cells over the table.
    return static_cast<std::size_t>(c.i * 73856093LL ^ c.j * 19349663LL ^ c.k * 83492791LL);
  }
};

}  // namespace

double weld_tolerance(const std::vector<Vec3>& vertices) {
  if (vertices.empty()) {
    return 0.0;
  }
  Vec3 lo = vertices.front();
  Vec3 hi = vertices.front();
  for (const Vec3& p : vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return 1e-6 * (hi - lo).norm();
}

WeldResult weld_vertices(const std::vector<Vec3>& vertices, double tolerance) {
  WeldResult result;
  result.node_of_vertex.resize(vertices.size());
  // A hash grid with cells of the tolerance's size: a vertex's match lies in its own cell or one
  // of the 26 around it.
  const double cell = tolerance > 0.0 ? tolerance : 1.0;
  std::unordered_map<CellKey, std::vector<Index>, CellHash> grid;
  auto key_of = [cell](const Vec3& p) {
    return CellKey{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                   static_cast<std::int64_t>(std::floor(p.y() / cell)),
                   static_cast<std::int64_t>(std::floor(p.z() / cell))};
  };
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const Vec3& p = vertices[v];
    const CellKey key = key_of(p);
    Index match = -1;
    for (int di = -1; di <= 1 && match < 0; ++di) {
      for (int dj = -1; dj <= 1 && match < 0; ++dj) {
        for (int dk = -1; dk <= 1 && match < 0; ++dk) {
          const auto it = grid.find(CellKey{key.i + di, key.j + dj, key.k + dk});
          if (it == grid.end()) {
            continue;
          }
          for (const Index node : it->second) {
            if ((result.nodes[node] - p).norm() <= tolerance) {
              match = node;
              break;
            }
          }
        }
      }
    }
    if (match < 0) {
      match = static_cast<Index>(result.nodes.size());
      result.nodes.push_back(p);
      grid[key].push_back(match);
    }
    result.node_of_vertex[v] = match;
  }
  return result;
}

}  // namespace dinam
