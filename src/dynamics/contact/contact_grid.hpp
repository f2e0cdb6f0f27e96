#pragma once
// The broad phase of contact: a uniform grid, hashed into buckets, of boxes. The cells are as
// wide as nine boxes in ten (the widest of the narrower 90 %); such a box is filed in the cell of
// its centre, so a box that overlaps a query has its centre within half a cell of it. A wider
// box (a long pole's bar beside a fine cloth's) is filed in every cell it covers and reported from
// the first of them that the query visits, so one long bar does not make every cell coarse; a box
// that would cover more than 64 cells is kept aside and checked by every query. Rebuilt by a
// counting sort into arrays kept between searches: nothing is allocated once they have grown. A
// bucket holds its boxes in increasing id order and a query visits its cells in a fixed order,
// so the candidates come in the same order for any thread count.
#include <algorithm>
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
  // About what the grid holds for each box it files in one cell, for the memory estimate: its
  // entry, its width while the cell is chosen, and its share of the buckets (between two and four
  // a box: a power of two at least twice the entries).
  static constexpr std::size_t bytes_per_box() {
    return sizeof(Entry) + sizeof(double) + 3 * sizeof(Index);
  }

  // Files boxes[id] for every id with use[id] != 0 (every id when `use` is empty), in cells at
  // least `min_cell` wide.
  void build(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& use, double min_cell);

  // visit(id) for every filed box that overlaps `box`, each once.
  template <class Visit>
  void visit_overlapping(const Box& box, const Visit& visit) const {
    // A narrow filed box that overlaps has its centre within half a cell of the query box.
    const Cell low = cell_of((box.min.array() - half_cell_).matrix());
    const Cell high = cell_of((box.max.array() + half_cell_).matrix());
    for (std::int64_t z = low.z; z <= high.z && !entries_.empty(); ++z) {
      for (std::int64_t y = low.y; y <= high.y; ++y) {
        for (std::int64_t x = low.x; x <= high.x; ++x) {
          const Cell cell{x, y, z};
          const std::uint64_t bucket = hash(cell) & mask_;
          for (Index k = bucket_start_[bucket]; k < bucket_start_[bucket + 1]; ++k) {
            const Entry& entry = entries_[k];
            // A bucket may also hold other cells' boxes (hash collisions): skip those; and a wide
            // box is reported only from the first of its cells that this query visits.
            if (entry.cell == cell && entry.box.overlaps(box) &&
                (!entry.wide ||
                 cell == Cell{std::max(low.x, entry.first.x), std::max(low.y, entry.first.y),
                              std::max(low.z, entry.first.z)})) {
              visit(entry.id);
            }
          }
        }
      }
    }
    for (const Entry& entry : aside_) {
      if (entry.box.overlaps(box)) {
        visit(entry.id);
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
    Cell first;  // a wide box's first cell (lowest in each axis)
    Box box;
    Index id = 0;
    bool wide = false;
  };
  Cell cell_of(const Vec3& p) const;
  static std::uint64_t hash(const Cell& cell);
  // Calls file(cell) for every cell the box's centre (narrow) or the box (wide) lies in.
  template <class File>
  void for_each_cell(const Box& box, bool wide, const File& file) const;

  double inverse_cell_ = 1.0;        // 1/m
  double half_cell_ = 0.5;           // m
  double cell_ = 1.0;                // m
  std::uint64_t mask_ = 0;           // bucket count − 1 (a power of two)
  std::vector<double> widths_;       // scratch: the filed boxes' widest sides
  std::vector<Index> bucket_start_;  // (n_buckets + 1) into entries_
  std::vector<Entry> entries_;       // bucket by bucket, ids increasing within one
  std::vector<Entry> aside_;         // boxes too wide to file, by id
};

}  // namespace dinam
