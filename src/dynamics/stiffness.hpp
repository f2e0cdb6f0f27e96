#pragma once
// The stiffness of a force kind, element by element: K_e = −∂f_e/∂x_e, the Jacobian of the forces
// an element (a spring, a touching node) puts on its nodes, negated, at the present positions with
// the histories (plastic sets) held as they are. For a conservative kind it is the Hessian of the
// element's energy. Newton's method (solver/) assembles them into the sparse stiffness of the
// whole model; dynamics/ only hands each element's matrix over, and never sees a global matrix.
//
// The spring kinds differentiate their own force kernels (templates on their scalar) in Dual
// numbers (core/dual.hpp), so the stiffness is exactly that of the forces the step applies.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "core/dual.hpp"
#include "core/error.hpp"
#include "core/thread_team.hpp"
#include "core/types.hpp"
#include "dynamics/broken.hpp"

namespace dinam {

// Where a kind hands each element's stiffness.
class StiffnessSink {
 public:
  // `stiffness` is (3 node_count × 3 node_count), column-major, symmetric, N/m: row and column
  // 3 k + a are node k's coordinate a. Pinned nodes may be among `nodes`; the sink drops them.
  // The same as prepare() on a copy, then add_prepared().
  void add(const Index* nodes, int node_count, const double* stiffness);

  // Makes an element's matrix, in place, what the sink takes (solver/'s sinks may project it to
  // positive semi-definite): by itself the costliest part of taking an element, so it changes
  // nothing of the sink and may run on any thread, for several elements at once.
  virtual void prepare(int node_count, double* stiffness) const = 0;
  // Takes an element's matrix as prepare() left it.
  virtual void add_prepared(const Index* nodes, int node_count, const double* stiffness) = 0;

 protected:
  StiffnessSink() = default;
  ~StiffnessSink() = default;
  StiffnessSink(const StiffnessSink&) = default;
  StiffnessSink& operator=(const StiffnessSink&) = default;
};

inline void StiffnessSink::add(const Index* nodes, int node_count, const double* stiffness) {
  std::array<double, 144> copy;  // the largest element's, 4 nodes
  const int size = 9 * node_count * node_count;
  DINAM_CHECK(node_count >= 1 && node_count <= 4);
  std::copy_n(stiffness, size, copy.data());
  prepare(node_count, copy.data());
  add_prepared(nodes, node_count, copy.data());
}

template <int kNodes>
using LocalStiffness = Eigen::Matrix<double, 3 * kNodes, 3 * kNodes>;

template <class T>
using Vec3Of = Eigen::Matrix<T, 3, 1>;

// −∂f/∂x of `forces`, a generic callable from the positions of an element's kNodes nodes
// (std::array of Vec3Of<T>) to the forces on them (the same), by forward-mode differentiation,
// symmetrised: a conservative force's Jacobian is symmetric but for rounding.
template <int kNodes, class Forces>
LocalStiffness<kNodes> local_stiffness(const std::array<Vec3, kNodes>& x, const Forces& forces) {
  using D = Dual<3 * kNodes>;
  std::array<Vec3Of<D>, kNodes> seeded;
  for (int j = 0; j < kNodes; ++j) {
    for (int a = 0; a < 3; ++a) {
      seeded[j][a] = D::input(x[j][a], 3 * j + a);
    }
  }
  const std::array<Vec3Of<D>, kNodes> f = forces(seeded);
  LocalStiffness<kNodes> k;
  for (int j = 0; j < kNodes; ++j) {
    for (int a = 0; a < 3; ++a) {
      for (int m = 0; m < 3 * kNodes; ++m) {
        k(3 * j + a, m) = -f[j][a].gradient[m];
      }
    }
  }
  return 0.5 * (k + k.transpose());
}

// Springs of a kind from which their matrices are computed on the process's team of threads
// (an element's matrix costs microseconds: dual numbers, and the sink's projection).
inline constexpr Index kMinParallelStiffness = 64;

// Springs whose matrices are computed at once before they are handed over: each thread's share of
// a chunk takes milliseconds, far more than starting the team, and the matrices held stay a few
// megabytes whatever the model (all of a million-bar cloth's torsion springs' were 1.2 GB).
inline constexpr Index kStiffnessChunk = 8192;

// The stiffness of every spring of a kind that is not broken: spring s has nodes
// nodes[kNodes s …], and stiffness(s, x) gives its matrix at their positions x. Chunk by chunk,
// the matrices are computed and prepared (StiffnessSink::prepare) on the process's team, each
// thread a range of the chunk's springs, then handed to the sink one thread in spring order: the
// same sums in the same order, whatever the number of threads.
template <int kNodes, class Stiffness>
void add_spring_stiffness(Index count, const std::vector<Index>& nodes,
                          const std::vector<std::uint8_t>& broken, const std::vector<Vec3>& x,
                          StiffnessSink& sink, const Stiffness& stiffness) {
  constexpr std::size_t kSize = 9 * kNodes * kNodes;
  // A chunk's matrices, kept from call to call (the kind's own, on the calling thread).
  thread_local std::vector<double> kept;
  std::vector<double>& matrices = kept;
  const Index chunk = std::min(count, kStiffnessChunk);
  matrices.resize(kSize * static_cast<std::size_t>(chunk));
  auto matrix_of = [&](Index s, Index first) {
    return &matrices[kSize * static_cast<std::size_t>(s - first)];
  };
  for (Index first = 0; first < count; first += chunk) {
    const Index last = std::min(first + chunk, count);
    auto compute = [&](Index begin, Index end) {
      for (Index s = begin; s < end; ++s) {
        if (is_broken(broken, s)) {
          continue;
        }
        const Index* spring = &nodes[static_cast<std::size_t>(kNodes) * s];
        std::array<Vec3, kNodes> at;
        for (int j = 0; j < kNodes; ++j) {
          at[j] = x[spring[j]];
        }
        double* matrix = matrix_of(s, first);
        Eigen::Map<LocalStiffness<kNodes>> element(matrix);
        element = stiffness(s, at);
        sink.prepare(kNodes, matrix);
      }
    };
    const bool shared = last - first >= kMinParallelStiffness && thread_count() > 1;
    thread_team().run(
        [&](const TeamMember& member) {
          const auto [begin, end] = member.share(last - first);
          compute(first + begin, first + end);
        },
        !shared);
    for (Index s = first; s < last; ++s) {
      if (!is_broken(broken, s)) {
        sink.add_prepared(&nodes[static_cast<std::size_t>(kNodes) * s], kNodes,
                          matrix_of(s, first));
      }
    }
  }
}

}  // namespace dinam
