#pragma once
// What the renderer's tests share.
#include <cstdint>

namespace dinam::test {

// A pixel's brightness, 0 to 255: the mean of its red, green and blue.
inline double brightness(const std::uint8_t* p) {
  return (p[0] + p[1] + p[2]) / 3.0;
}

}  // namespace dinam::test
