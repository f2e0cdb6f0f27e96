#include "io/image_compare.hpp"

#include <algorithm>
#include <cstdlib>

namespace dinam {

ImageComparison compare_images(const Image& actual, const Image& expected, int threshold) {
  ImageComparison result;
  result.same_size = actual.width == expected.width && actual.height == expected.height;
  if (!result.same_size) {
    result.differing_fraction = 1.0;
    result.mean_error = 255.0;
    result.difference = actual;
    return result;
  }
  result.difference = Image(actual.width, actual.height);
  const std::size_t pixels = static_cast<std::size_t>(actual.width) * actual.height;
  std::size_t differing = 0;
  double error_sum = 0.0;
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::uint8_t* a = actual.rgba.data() + 4 * p;
    const std::uint8_t* e = expected.rgba.data() + 4 * p;
    int largest = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int{a[c]} - int{e[c]});
      largest = std::max(largest, d);
      error_sum += d;
    }
    std::uint8_t* out = result.difference.rgba.data() + 4 * p;
    if (largest > threshold) {
      ++differing;
      out[0] = 255;
      out[1] = 0;
      out[2] = 0;
    } else {
      const auto grey = static_cast<std::uint8_t>((a[0] + a[1] + a[2]) / 6);
      out[0] = out[1] = out[2] = grey;
    }
    out[3] = 255;
  }
  result.differing_fraction = static_cast<double>(differing) / static_cast<double>(pixels);
  result.mean_error = error_sum / (3.0 * static_cast<double>(pixels));
  return result;
}

}  // namespace dinam
