#pragma once
// Comparing a rendered picture with a golden one under a stated tolerance. Software OpenGL differs
// slightly between Mesa and LLVM builds (rounding at triangle edges, anti-aliasing), and a camera
// a fraction of a pixel away moves every edge by that fraction, so images are never compared byte
// for byte. Three measures, each with its limit:
//  - the pixels that differ: a pixel differs when some channel lies further than `threshold` from
//    every value the other picture has within `shift` pixels of it (outside the range of that
//    neighbourhood), either way round. An edge moved by under a pixel blends values its
//    neighbours already span, so it passes; a moved object or a changed colour does not;
//  - the mean error of every channel of every pixel, which catches a faint change everywhere;
//  - the structural similarity (SSIM, Wang, Bovik, Sheikh and Simoncelli 2004: luminance, a
//    Gaussian window of σ = 1.5 px, K1 = 0.01, K2 = 0.03), a perceptual measure of whether the
//    picture's structure (edges, texture, contrast) is the same: 1 for the same picture; chosen
//    over FLIP for being the measure CI tools and papers report, defined in a page and needing no
//    viewing distance or display to be assumed.
// The default limits, measured on the paper's flag at 320 × 180: its camera moved by a quarter
// and by half a pixel, 0.04–0.07 % of pixels differ, mean error 0.2–0.5, SSIM 0.992–0.998 (all
// pass); its pole moved by 5 cm (3 px), 0.7–0.9 %, 0.8–1.3 and 0.967–0.981 (each fails).
// A weight per pixel (0 masks it out, 2 counts it twice) lets a region matter less or more.
#include <string>
#include <vector>

#include "core/image.hpp"

namespace dinam {

struct ImageTolerance {
  int threshold = 24;                     // 0–255: how far a channel may lie from its neighbours'
  int shift = 1;                          // pixels: how far an edge may have moved
  double max_differing_fraction = 0.005;  // of the pixels, weighed
  double max_mean_error = 1.0;            // 0–255, over every channel of every pixel, weighed
  double min_ssim = 0.99;                 // the mean structural similarity, weighed
};

struct ImageComparison {
  bool same_size = false;
  double differing_fraction = 0.0;
  double mean_error = 0.0;
  double ssim = 1.0;
  // The actual picture dimmed to grey, differing pixels in red, pixels masked out in dark blue.
  Image difference;

  bool matches(const ImageTolerance& tolerance) const {
    return same_size && differing_fraction <= tolerance.max_differing_fraction &&
           mean_error <= tolerance.max_mean_error && ssim >= tolerance.min_ssim;
  }
  // What passed its limit, for a message: "12.5 % of pixels differ (allowed 0.5 %); …".
  std::string failures(const ImageTolerance& tolerance) const;
};

// `weights` holds one weight (≥ 0) per pixel, row by row, or is empty (every pixel 1).
ImageComparison compare_images(const Image& actual, const Image& expected,
                               const ImageTolerance& tolerance,
                               const std::vector<float>& weights = {});

// The mean structural similarity of the two pictures' luminance (same size), each pixel's SSIM
// weighed by `weights` (empty: all 1).
double structural_similarity(const Image& a, const Image& b,
                             const std::vector<float>& weights = {});

}  // namespace dinam
