#pragma once
// The broad phase of contact: a uniform grid, hashed into buckets, of boxes by their centres.
// With cells at least as wide as the widest box (queried or stored), two boxes that overlap have
// their centres in the same or neighbouring cells, so a query visits 27 cells and the cost of a
// step's search grows linearly with the number of boxes. Rebuilt every step by a counting sort
// into arrays kept between steps: nothing is allocated once they have grown. A bucket holds its
// boxes in increasing id order and a query visits its cells in a fixed order, so the candidates
// come in the same order for any thread count.
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Box {
  Vec3 min;
  Vec3 max;

  bool overlaps(const Box& other) const {
    return (min.array() <= other.max.array()).all() && (other.min.array() <= max.array()).all();
  }
  double widest_side() const { return (max - min).maxCoeff(); }
};

class ContactGrid {
 public:
  // Files boxes[id] for every id with use[id] != 0 (every id when `use` is empty), in cells as
  // wide as the widest of them and at least `min_cell` (the widest box that will be queried).
  void build(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& use, double min_cell);

  // visit(id) for every filed box that overlaps `box` (as wide as `min_cell` at most), each once.
  template <class Visit>
  void visit_overlapping(const Box& box, const Visit& visit) const {
    if (entries_.empty()) {
      return;
    }
    // A filed box that overlaps has its centre within half a cell of the query box.
    const Cell low = cell_of((box.min.array() - half_cell_).matrix());
    const Cell high = cell_of((box.max.array() + half_cell_).matrix());
    for (std::int64_t z = low.z; z <= high.z; ++z) {
      for (std::int64_t y = low.y; y <= high.y; ++y) {
        for (std::int64_t x = low.x; x <= high.x; ++x) {
          const Cell cell{x, y, z};
          const std::uint64_t bucket = hash(cell) & mask_;
          for (Index k = bucket_start_[bucket]; k < bucket_start_[bucket + 1]; ++k) {
            const Entry& entry = entries_[k];
            // A bucket may also hold other cells' boxes (hash collisions): skip those, so that
            // no box is visited twice.
            if (entry.cell == cell && entry.box.overlaps(box)) {
              visit(entry.id);
            }
          }
        }
      }
    }
  }

 private:
  struct Cell {
    std::int64_t x = 0, y = 0, z = 0;
    bool operator==(const Cell&) const = default;
  };
  // A filed box with its cell, kept together so that a query reads its buckets in one sweep.
  struct Entry {
    Cell cell;
    Box box;
    Index id = 0;
  };
  Cell cell_of(const Vec3& p) const;
  static std::uint64_t hash(const Cell& cell);

  double inverse_cell_ = 1.0;             // 1/m
  double half_cell_ = 0.5;                // m
  std::uint64_t mask_ = 0;                // bucket count − 1 (a power of two)
  std::vector<std::uint64_t> bucket_of_;  // (n_boxes) scratch: each filed box's bucket
  std::vector<Index> bucket_start_;       // (n_buckets + 1) into entries_
  std::vector<Entry> entries_;            // bucket by bucket, ids increasing within one
};

}  // namespace dinam
