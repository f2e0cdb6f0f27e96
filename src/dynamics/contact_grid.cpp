#include "dynamics/contact_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace dinam {

ContactGrid::Cell ContactGrid::cell_of(const Vec3& p) const {
  return {static_cast<std::int64_t>(std::floor(p.x() * inverse_cell_)),
          static_cast<std::int64_t>(std::floor(p.y() * inverse_cell_)),
          static_cast<std::int64_t>(std::floor(p.z() * inverse_cell_))};
}

std::uint64_t ContactGrid::hash(const Cell& cell) {
  // Three large odd multipliers mix the coordinates; the top bits are folded down.
  std::uint64_t h = static_cast<std::uint64_t>(cell.x) * 0x9E3779B97F4A7C15ULL ^
                    static_cast<std::uint64_t>(cell.y) * 0xC2B2AE3D27D4EB4FULL ^
                    static_cast<std::uint64_t>(cell.z) * 0x165667B19E3779F9ULL;
  return h ^ (h >> 29);
}

void ContactGrid::build(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& use,
                        double min_cell) {
  const auto count = static_cast<Index>(boxes.size());
  auto used = [&](Index id) { return use.empty() || use[id] != 0; };
  double widest = min_cell;
  Index filed = 0;
  for (Index id = 0; id < count; ++id) {
    if (used(id)) {
      widest = std::max(widest, boxes[id].widest_side());
      ++filed;
    }
  }
  entries_.clear();
  if (filed == 0) {
    return;
  }
  inverse_cell_ = widest > 0.0 ? 1.0 / widest : 1.0;
  half_cell_ = 0.5 * widest;
  const std::uint64_t buckets = std::bit_ceil(2 * static_cast<std::uint64_t>(filed));
  mask_ = buckets - 1;
  bucket_of_.resize(boxes.size());
  bucket_start_.assign(buckets + 1, 0);
  for (Index id = 0; id < count; ++id) {
    if (used(id)) {
      bucket_of_[id] = hash(cell_of(0.5 * (boxes[id].min + boxes[id].max))) & mask_;
      ++bucket_start_[bucket_of_[id] + 1];
    }
  }
  for (std::uint64_t b = 0; b < buckets; ++b) {
    bucket_start_[b + 1] += bucket_start_[b];
  }
  // Filled in increasing id order, using the starts as cursors and then restoring them.
  entries_.resize(static_cast<std::size_t>(filed));
  for (Index id = 0; id < count; ++id) {
    if (used(id)) {
      entries_[bucket_start_[bucket_of_[id]]++] = {cell_of(0.5 * (boxes[id].min + boxes[id].max)),
                                                   boxes[id], id};
    }
  }
  for (std::uint64_t b = buckets; b > 0; --b) {
    bucket_start_[b] = bucket_start_[b - 1];
  }
  bucket_start_[0] = 0;
}

}  // namespace dinam
