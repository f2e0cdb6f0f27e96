#pragma once
// The sRGB transfer function (IEC 61966-2-1): how a colour as a picker shows it (and as an 8-bit
// image stores it) maps to linear light, in which shading adds and multiplies.
#include <cmath>

namespace dinam {

inline double srgb_to_linear(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

inline double linear_to_srgb(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace dinam
