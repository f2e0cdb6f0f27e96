#pragma once
// Comparing a rendered picture with a golden one under a stated tolerance. Software OpenGL differs
// slightly between Mesa and LLVM builds (rounding at triangle edges, anti-aliasing), so images are
// never compared byte for byte: a pixel counts as different when some channel differs by more
// than `threshold`, and the pictures match when few pixels differ and the mean error is small.
#include "core/image.hpp"

namespace dinam {

struct ImageTolerance {
  int threshold = 24;  // 0–255: a channel difference above this marks the pixel
  double max_differing_fraction = 0.005;  // of all pixels
  double max_mean_error = 1.0;            // 0–255, over every channel of every pixel
};

struct ImageComparison {
  bool same_size = false;
  double differing_fraction = 0.0;
  double mean_error = 0.0;
  Image difference;  // the actual picture dimmed to grey, differing pixels in red

  bool matches(const ImageTolerance& tolerance) const {
    return same_size && differing_fraction <= tolerance.max_differing_fraction &&
           mean_error <= tolerance.max_mean_error;
  }
};

ImageComparison compare_images(const Image& actual, const Image& expected, int threshold);

}  // namespace dinam
