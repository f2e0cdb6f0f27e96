#include "model/vertex_welding.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

namespace dinam {
namespace {

// A hash grid over the kept vertices, flat: cells of twice the tolerance, so that the ball of
// radius `tolerance` around a point overlaps at most the 2 × 2 × 2 cells nearest to it (its own
// and, along each axis, the neighbour on the side it is closer to). Each cell holds a chain of its
// vertices through `next`, headed by the latest; the table is open-addressed with linear probing,
// a slot holding the head and the cell's hash (a head's position gives its cell back). A
// million-vertex mesh welds in about 0.1 s this way, where a map of vectors probed at 27 cells
// took 2 s.
class WeldGrid {
 public:
  struct Cell {
    std::int64_t i = 0, j = 0, k = 0;
    bool operator==(const Cell&) const = default;
  };

  WeldGrid(std::size_t capacity, double cell)
      : cell_(cell), mask_(std::bit_ceil(capacity + capacity / 2 + 16) - 1), slots_(mask_ + 1) {}

  // The cell holding p, and along each axis whether its nearer neighbour is above (+1) or below.
  Cell cell_of(const Vec3& p, int side[3]) const {
    const Vec3 scaled = p / cell_;
    const Vec3 floor = scaled.array().floor();
    for (int a = 0; a < 3; ++a) {
      side[a] = scaled[a] - floor[a] < 0.5 ? -1 : 1;
    }
    return {static_cast<std::int64_t>(floor.x()), static_cast<std::int64_t>(floor.y()),
            static_cast<std::int64_t>(floor.z())};
  }

  // The slot of `cell`: its own, or the empty one where it would go.
  std::size_t find(const Cell& cell, const std::vector<Vec3>& nodes) const {
    const std::uint64_t h = hash(cell);
    const auto tag = static_cast<std::uint32_t>(h >> 32);
    int side[3];
    for (std::size_t s = h & mask_;; s = (s + 1) & mask_) {
      const Slot& slot = slots_[s];
      if (slot.head < 0 || (slot.tag == tag && cell_of(nodes[slot.head], side) == cell)) {
        return s;
      }
    }
  }

  Index head(std::size_t slot) const { return slots_[slot].head; }

  // Puts kept vertex `node` at the front of the chain of `cell`, whose slot find() gave.
  void insert(std::size_t slot, const Cell& cell, Index node, std::vector<Index>& next) {
    next[node] = slots_[slot].head;
    slots_[slot] = {node, static_cast<std::uint32_t>(hash(cell) >> 32)};
  }

 private:
  struct Slot {
    Index head = -1;
    std::uint32_t tag = 0;  // the high half of the cell's hash
  };

  static std::uint64_t hash(const Cell& c) {
    // Large odd multipliers spread neighbouring cells over the table; the high bits mixed down.
    const std::uint64_t h = static_cast<std::uint64_t>(c.i) * 0x9E3779B97F4A7C15ULL ^
                            static_cast<std::uint64_t>(c.j) * 0xC2B2AE3D27D4EB4FULL ^
                            static_cast<std::uint64_t>(c.k) * 0x165667B19E3779F9ULL;
    return h ^ (h >> 29);
  }

  double cell_;
  std::size_t mask_;
  std::vector<Slot> slots_;
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
  result.nodes.reserve(vertices.size());
  WeldGrid grid(vertices.size(), tolerance > 0.0 ? 2.0 * tolerance : 1.0);
  std::vector<Index> next(vertices.size());  // the chain of each cell, through kept vertices
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const Vec3& p = vertices[v];
    int side[3];
    const WeldGrid::Cell own = grid.cell_of(p, side);
    // The earliest kept vertex within the tolerance, whichever of the eight cells holds it.
    Index match = -1;
    std::size_t own_slot = 0;
    for (int corner = 0; corner < 8; ++corner) {
      const WeldGrid::Cell cell{own.i + ((corner & 1) != 0 ? side[0] : 0),
                                own.j + ((corner & 2) != 0 ? side[1] : 0),
                                own.k + ((corner & 4) != 0 ? side[2] : 0)};
      const std::size_t slot = grid.find(cell, result.nodes);
      own_slot = corner == 0 ? slot : own_slot;
      for (Index node = grid.head(slot); node >= 0; node = next[node]) {
        if ((match < 0 || node < match) && (result.nodes[node] - p).norm() <= tolerance) {
          match = node;
        }
      }
    }
    if (match < 0) {
      match = static_cast<Index>(result.nodes.size());
      result.nodes.push_back(p);
      grid.insert(own_slot, own, match, next);
    }
    result.node_of_vertex[v] = match;
  }
  result.nodes.shrink_to_fit();
  return result;
}

}  // namespace dinam
