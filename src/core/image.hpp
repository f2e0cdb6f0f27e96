#pragma once
// An 8-bit RGBA image stored top row first, 4 bytes per pixel: what the renderer produces and
// the PNG writer consumes.
#include <cstdint>
#include <vector>

namespace dinam {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // (height × width × 4), row 0 is the top of the picture

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}

  const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
  }
};

}  // namespace dinam
