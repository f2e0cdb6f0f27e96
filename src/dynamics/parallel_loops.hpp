#pragma once
// The two ways the force loops and the integrator share work between OpenMP threads without
// changing a bit of the result: per-node loops, where each iteration writes only its own node,
// and spring loops taken colour by colour (model/spring_colouring.hpp), where the blocks of
// springs of one colour touch disjoint nodes. No sum anywhere depends on how iterations are
// scheduled.
#include <algorithm>

#include "core/types.hpp"
#include "model/spring_colouring.hpp"

namespace dinam {

// Loops shorter than this run on the calling thread alone: below it, waking the other threads
// costs more than they save (a few microseconds per loop with libgomp).
inline constexpr Index kMinParallelItems = 4096;

// body(i) for i in [0, count), each i writing only data of its own: shared between the threads
// when `parallel`, on the calling thread otherwise.
// (Short loops never enter the OpenMP runtime at all: even a parallel region that the `if`
// clause turns off costs about a microsecond, which a small model's step cannot afford.)
template <class Body>
void for_each_index_if(Index count, bool parallel, const Body& body) {
  if (!parallel) {
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

// body(i) for i in [0, count), each i writing only data of its own.
template <class Body>
void for_each_index(Index count, const Body& body) {
  for_each_index_if(count, count >= kMinParallelItems, body);
}

// Whether body(i) is true for any i in [0, count), body(i) run for every i (each writing only
// data of its own): a logical OR, so the answer does not depend on the threads either.
template <class Body>
bool any_index(Index count, const Body& body) {
  bool any = false;
  if (count < kMinParallelItems) {
    for (Index i = 0; i < count; ++i) {
      any = body(i) || any;
    }
    return any;
  }
#pragma omp parallel for schedule(static) reduction(|| : any)
  for (Index i = 0; i < count; ++i) {
    any = body(i) || any;
  }
  return any;
}

// body(first, size) for the blocks [first, first + size) of at most `block_size` items that
// cover [0, count), each block writing only data of its own: for loops that gather a block of
// items, compute it in SIMD lanes and store it (the wind's nodes and faces, the ground's nodes).
// The blocks do not depend on the thread count, so neither does anything computed in them.
template <class Body>
void for_each_block(Index count, Index block_size, const Body& body) {
  const Index blocks = (count + block_size - 1) / block_size;
  for_each_index_if(blocks, count >= kMinParallelItems, [&](Index b) {
    const Index first = b * block_size;
    body(first, std::min(block_size, count - first));
  });
}

// body(first, count) for every block of springs (model/spring_colouring.hpp), the springs
// [first, first + count) in one call, colour after colour; the blocks of a colour in parallel.
// A kind with fewer springs than kMinParallelItems runs on the calling thread, in the same order.
template <class Body>
void for_each_spring_block(const SpringColouring& colouring, const Body& body) {
  auto run_block = [&](Index k) {
    const Index block = colouring.blocks[k];
    body(SpringColouring::first_spring(block), colouring.block_size(block));
  };
  const bool parallel = colouring.spring_count >= kMinParallelItems;
  for (Index c = 0; c < colouring.colour_count(); ++c) {
    const Index begin = colouring.offsets[c];
    const Index end = colouring.offsets[c + 1];
    if (!parallel) {
      for (Index k = begin; k < end; ++k) {
        run_block(k);
      }
      continue;
    }
#pragma omp parallel for schedule(static)
    for (Index k = begin; k < end; ++k) {
      run_block(k);
    }
  }
}

// body(s) for every spring, in the order and with the sharing of for_each_spring_block.
template <class Body>
void for_each_spring(const SpringColouring& colouring, const Body& body) {
  for_each_spring_block(colouring, [&](Index first, Index count) {
    for (Index s = first; s < first + count; ++s) {
      body(s);
    }
  });
}

}  // namespace dinam
