#pragma once
// Wall time, for what a run reports it took (never for what it decides: estimates come from
// counts).
#include <chrono>

namespace dinam {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace dinam
