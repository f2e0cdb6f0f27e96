#include "dynamics/contact/contact_grid.hpp"

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

namespace {

constexpr std::int64_t kMostCellsOfABox = 64;

}  // namespace

template <class File>
void ContactGrid::for_each_cell(const Box& box, bool wide, const File& file) const {
  if (!wide) {
    file(cell_of(0.5 * (box.min + box.max)), cell_of(box.min));
    return;
  }
  const Cell low = cell_of(box.min);
  const Cell high = cell_of(box.max);
  for (std::int64_t z = low.z; z <= high.z; ++z) {
    for (std::int64_t y = low.y; y <= high.y; ++y) {
      for (std::int64_t x = low.x; x <= high.x; ++x) {
        file(Cell{x, y, z}, low);
      }
    }
  }
}

void ContactGrid::build(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& use,
                        double min_cell) {
  const auto count = static_cast<Index>(boxes.size());
  auto used = [&](Index id) { return use.empty() || use[id] != 0; };
  entries_.clear();
  aside_.clear();
  // The cell: the widest of the narrower nine boxes in ten.
  widths_.clear();
  for (Index id = 0; id < count; ++id) {
    if (used(id)) {
      widths_.push_back(boxes[id].widest_side());
    }
  }
  if (widths_.empty()) {
    return;
  }
  const auto ninety = widths_.begin() + static_cast<std::ptrdiff_t>((widths_.size() * 9) / 10);
  std::nth_element(widths_.begin(), ninety, widths_.end());
  cell_ = std::max(min_cell, *ninety);
  cell_ = cell_ > 0.0 ? cell_ : 1.0;
  inverse_cell_ = 1.0 / cell_;
  half_cell_ = 0.5 * cell_;
  // Which boxes are wide, and how many entries they make; the widest are kept aside.
  auto cells_of = [&](const Box& box) {
    const Cell low = cell_of(box.min);
    const Cell high = cell_of(box.max);
    return (high.x - low.x + 1) * (high.y - low.y + 1) * (high.z - low.z + 1);
  };
  std::uint64_t filed = 0;
  for (Index id = 0; id < count; ++id) {
    if (!used(id)) {
      continue;
    }
    if (boxes[id].widest_side() <= cell_) {
      ++filed;
    } else if (const std::int64_t cells = cells_of(boxes[id]); cells <= kMostCellsOfABox) {
      filed += static_cast<std::uint64_t>(cells);
    } else {
      aside_.push_back({{}, {}, boxes[id], id, true});
    }
  }
  const std::uint64_t buckets = std::bit_ceil(2 * std::max<std::uint64_t>(filed, 1));
  mask_ = buckets - 1;
  bucket_start_.assign(buckets + 1, 0);
  auto each_filed = [&](auto&& file) {
    for (Index id = 0; id < count; ++id) {
      if (!used(id)) {
        continue;
      }
      const bool wide = boxes[id].widest_side() > cell_;
      if (!wide || cells_of(boxes[id]) <= kMostCellsOfABox) {
        for_each_cell(boxes[id], wide,
                      [&](const Cell& cell, const Cell& first) { file(id, wide, cell, first); });
      }
    }
  };
  each_filed([&](Index, bool, const Cell& cell, const Cell&) {
    ++bucket_start_[(hash(cell) & mask_) + 1];
  });
  for (std::uint64_t b = 0; b < buckets; ++b) {
    bucket_start_[b + 1] += bucket_start_[b];
  }
  // Filled in increasing id order, using the starts as cursors and then restoring them.
  entries_.resize(static_cast<std::size_t>(filed));
  each_filed([&](Index id, bool wide, const Cell& cell, const Cell& first) {
    entries_[bucket_start_[hash(cell) & mask_]++] = {cell, first, boxes[id], id, wide};
  });
  for (std::uint64_t b = buckets; b > 0; --b) {
    bucket_start_[b] = bucket_start_[b - 1];
  }
  bucket_start_[0] = 0;
}

}  // namespace dinam
