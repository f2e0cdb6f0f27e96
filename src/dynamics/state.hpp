#pragma once
// Everything that changes during a run. The model it belongs to is passed beside it.
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

// Leapfrog state at step n: positions at whole steps, velocities at half steps.
struct State {
  double time = 0.0;         // s, t_n
  std::int64_t step = 0;     // n
  std::vector<Vec3> x;       // (n_nodes) m, x_n
  std::vector<Vec3> v_half;  // (n_nodes) m/s, v_{n-½}
  std::vector<Vec3> force;   // (n_nodes) N, scratch: the total force at t_n on each node
};

}  // namespace dinam
