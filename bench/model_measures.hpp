#pragma once
// What the plain benchmark programs count about a model.
#include <malloc.h>

#include "model/model.hpp"

namespace dinam {

// Heap in use now, bytes: what is allocated and not yet freed (glibc's mallinfo2, small blocks
// and mmap'ed large ones). Unlike the resident set it does not count heap that building the model
// used, freed and glibc keeps for reuse.
inline double heap_bytes_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return static_cast<double>(info.uordblks + info.hblkhd);
}

// Springs of every kind that a step evaluates.
inline Index spring_count(const Model& model) {
  return model.bar_count() + model.bend_count() + model.torsion_count();
}

}  // namespace dinam
