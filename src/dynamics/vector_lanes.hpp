#pragma once
// 3-vectors of a block of items by coordinate (structure of arrays): the layout in which the force
// loops gather a block, compute one item per SIMD lane and store it (spring_block.hpp, wind.cpp,
// ground_contact.cpp).
#include "core/types.hpp"

namespace dinam {

template <Index kLanes>
struct Vec3Lanes {
  double coordinate[3][kLanes];  // coordinate[axis][k]: item k's vector

  Vec3 get(Index k) const { return {coordinate[0][k], coordinate[1][k], coordinate[2][k]}; }
  void set(Index k, const Vec3& value) {
    coordinate[0][k] = value.x();
    coordinate[1][k] = value.y();
    coordinate[2][k] = value.z();
  }
};

}  // namespace dinam
