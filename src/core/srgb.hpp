#pragma once
// The sRGB transfer function (IEC 61966-2-1): how a colour as a picker shows it (and as an 8-bit
// image stores it) maps to linear light, in which shading adds and multiplies. (The display's
// encoding back is shaders/display.glsl's.)
#include <cmath>

namespace dinam {

inline double srgb_to_linear(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace dinam
