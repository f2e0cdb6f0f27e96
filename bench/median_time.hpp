#pragma once
// The timing the plain benchmark programs share.
#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace dinam {

// The median of `repeats` timings of `run`, in seconds.
inline double median_seconds(int repeats, const std::function<void()>& run) {
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace dinam
