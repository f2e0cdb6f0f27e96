#pragma once
// The box the automatic camera frames in one frame: per axis, the node coordinates between the
// 1st and the 99th percentile. A few nodes flung far away (a torn-off fragment, a stray vertex of
// a downloaded file) then do not shrink the model to a speck; a model of fewer than a hundred
// nodes keeps its whole box. The motion cache stores it per frame, so that frames drawn from a
// cache are framed as those drawn from the scene.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/types.hpp"

namespace dinam {

// The fraction of nodes at each end of each axis that framing may leave out.
inline constexpr double kSubjectOutlierFraction = 0.01;

inline void subject_box(const std::vector<Vec3f>& positions, Vec3f& lo, Vec3f& hi) {
  if (positions.empty()) {
    lo = hi = Vec3f::Zero();
    return;
  }
  const std::size_t n = positions.size();
  const auto left_out =
      static_cast<std::size_t>(std::floor(kSubjectOutlierFraction * static_cast<double>(n)));
  std::vector<float> coordinate(n);
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t i = 0; i < n; ++i) {
      coordinate[i] = positions[i][axis];
    }
    const auto low = coordinate.begin() + static_cast<std::ptrdiff_t>(left_out);
    std::nth_element(coordinate.begin(), low, coordinate.end());
    lo[axis] = *low;
    const auto high = coordinate.begin() + static_cast<std::ptrdiff_t>(n - 1 - left_out);
    std::nth_element(low, high, coordinate.end());
    hi[axis] = *high;
  }
}

}  // namespace dinam
