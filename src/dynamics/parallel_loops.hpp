#pragma once
// The two ways the force loops and the integrator share work between OpenMP threads without
// changing a bit of the result: per-node loops, where each iteration writes only its own node,
// and spring loops taken colour by colour (model/spring_colouring.hpp), where the springs of one
// colour touch disjoint nodes. No sum anywhere depends on how iterations are scheduled.
#include <algorithm>

#include "core/types.hpp"
#include "model/spring_colouring.hpp"

namespace dinam {

// Loops shorter than this run on the calling thread alone: below it, waking the other threads
// costs more than they save (a few microseconds per loop with libgomp).
inline constexpr Index kMinParallelItems = 4096;

// body(i) for i in [0, count), each i writing only data of its own.
// (Short loops never enter the OpenMP runtime at all: even a parallel region that the `if`
// clause turns off costs about a microsecond, which a small model's step cannot afford.)
template <class Body>
void for_each_index(Index count, const Body& body) {
  if (count < kMinParallelItems) {
    for (Index i = 0; i < count; ++i) {
      body(i);
    }
    return;
  }
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < count; ++i) {
    body(i);
  }
}

// body(s) for every spring, colour after colour; within a colour in parallel.
template <class Body>
void for_each_spring_by_colour(const SpringColouring& colouring, const Body& body) {
  const auto count = static_cast<Index>(colouring.order.size());
  if (count < kMinParallelItems) {
    for (Index k = 0; k < count; ++k) {
      body(colouring.order[k]);
    }
    return;
  }
  for (Index c = 0; c < colouring.colour_count(); ++c) {
    const Index begin = colouring.offsets[c];
    const Index end = colouring.offsets[c + 1];
#pragma omp parallel for schedule(static)
    for (Index k = begin; k < end; ++k) {
      body(colouring.order[k]);
    }
  }
}

// How many springs one block holds: a block's results (spring_block.hpp) stay in the first-level
// cache between the pass that computes them and the pass that adds them to the nodes.
inline constexpr Index kSpringBlockSize = 64;

// body(springs, count) for every spring in blocks of at most kSpringBlockSize consecutive ids of
// colouring.order (`springs` points into it). In parallel, a block holds springs of one colour
// and the blocks of a colour are shared between threads, colour after colour. A short loop runs
// on the calling thread and its blocks may span colours, since it visits the order in sequence
// anyway: fewer, fuller blocks, and the same order of sums as the parallel loop.
template <class Body>
void for_each_spring_block(const SpringColouring& colouring, const Body& body) {
  const auto count = static_cast<Index>(colouring.order.size());
  if (count < kMinParallelItems) {
    for (Index first = 0; first < count; first += kSpringBlockSize) {
      body(&colouring.order[first], std::min(kSpringBlockSize, count - first));
    }
    return;
  }
  for (Index c = 0; c < colouring.colour_count(); ++c) {
    const Index begin = colouring.offsets[c];
    const Index end = colouring.offsets[c + 1];
    const Index blocks = (end - begin + kSpringBlockSize - 1) / kSpringBlockSize;
#pragma omp parallel for schedule(static)
    for (Index block = 0; block < blocks; ++block) {
      const Index first = begin + block * kSpringBlockSize;
      body(&colouring.order[first], std::min(kSpringBlockSize, end - first));
    }
  }
}

}  // namespace dinam
