#include "io/image_compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

namespace dinam {
namespace {

// Each channel's least and greatest value within `shift` pixels of every pixel (a square
// neighbourhood, clamped at the picture's border), computed as two separable passes.
struct ChannelRange {
  std::vector<std::uint8_t> low;   // (pixels × 3)
  std::vector<std::uint8_t> high;  // (pixels × 3)
};

// `range` widened along one axis: each entry's least and greatest over the entries within
// `shift` of it along x (or y), clamped at the border.
ChannelRange widened(const ChannelRange& range, int w, int h, int shift, bool along_x) {
  ChannelRange out{std::vector<std::uint8_t>(range.low.size()),
                   std::vector<std::uint8_t>(range.high.size())};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int at = along_x ? x : y;
      const int last = along_x ? w - 1 : h - 1;
      for (int c = 0; c < 3; ++c) {
        std::uint8_t low = 255;
        std::uint8_t high = 0;
        for (int i = std::max(0, at - shift); i <= std::min(last, at + shift); ++i) {
          const std::size_t q = 3 * (along_x ? static_cast<std::size_t>(y) * w + i
                                             : static_cast<std::size_t>(i) * w + x) +
                                c;
          low = std::min(low, range.low[q]);
          high = std::max(high, range.high[q]);
        }
        const std::size_t p = 3 * (static_cast<std::size_t>(y) * w + x) + c;
        out.low[p] = low;
        out.high[p] = high;
      }
    }
  }
  return out;
}

ChannelRange neighbourhood_range(const Image& image, int shift) {
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  ChannelRange values{std::vector<std::uint8_t>(pixels * 3), {}};
  for (std::size_t p = 0; p < pixels; ++p) {
    for (int c = 0; c < 3; ++c) {
      values.low[3 * p + c] = image.rgba[4 * p + c];
    }
  }
  values.high = values.low;
  const ChannelRange rows = widened(values, image.width, image.height, shift, true);
  return widened(rows, image.width, image.height, shift, false);
}

// Whether some channel of `value` lies further than `threshold` outside [low, high].
bool outside(const std::uint8_t* value, const std::uint8_t* low, const std::uint8_t* high,
             int threshold) {
  for (int c = 0; c < 3; ++c) {
    if (int{value[c]} < int{low[c]} - threshold || int{value[c]} > int{high[c]} + threshold) {
      return true;
    }
  }
  return false;
}

// A picture's luminance (Rec. 601 weights on the stored values, as SSIM is usually taken).
std::vector<double> luminance(const Image& image) {
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  std::vector<double> y(pixels);
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::uint8_t* v = image.rgba.data() + 4 * p;
    y[p] = 0.299 * v[0] + 0.587 * v[1] + 0.114 * v[2];
  }
  return y;
}

// The 11-tap Gaussian of σ = 1.5 px that SSIM's local statistics are weighed by, normalised.
std::array<double, 11> gaussian_window() {
  std::array<double, 11> taps{};
  double sum = 0.0;
  for (int i = 0; i < 11; ++i) {
    const double d = i - 5;
    taps[i] = std::exp(-d * d / (2.0 * 1.5 * 1.5));
    sum += taps[i];
  }
  for (double& t : taps) {
    t /= sum;
  }
  return taps;
}

// `values` blurred by the window, rows then columns, the border clamped.
std::vector<double> blurred(const std::vector<double>& values, int w, int h) {
  static const std::array<double, 11> taps = gaussian_window();
  std::vector<double> across(values.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double sum = 0.0;
      for (int k = -5; k <= 5; ++k) {
        sum += taps[k + 5] * values[static_cast<std::size_t>(y) * w + std::clamp(x + k, 0, w - 1)];
      }
      across[static_cast<std::size_t>(y) * w + x] = sum;
    }
  }
  std::vector<double> out(values.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double sum = 0.0;
      for (int k = -5; k <= 5; ++k) {
        sum += taps[k + 5] * across[static_cast<std::size_t>(std::clamp(y + k, 0, h - 1)) * w + x];
      }
      out[static_cast<std::size_t>(y) * w + x] = sum;
    }
  }
  return out;
}

}  // namespace

double structural_similarity(const Image& a, const Image& b, const std::vector<float>& weights) {
  const int w = a.width;
  const int h = a.height;
  const std::vector<double> x = luminance(a);
  const std::vector<double> y = luminance(b);
  std::vector<double> xx(x.size());
  std::vector<double> yy(x.size());
  std::vector<double> xy(x.size());
  for (std::size_t p = 0; p < x.size(); ++p) {
    xx[p] = x[p] * x[p];
    yy[p] = y[p] * y[p];
    xy[p] = x[p] * y[p];
  }
  const std::vector<double> mx = blurred(x, w, h);
  const std::vector<double> my = blurred(y, w, h);
  const std::vector<double> sxx = blurred(xx, w, h);
  const std::vector<double> syy = blurred(yy, w, h);
  const std::vector<double> sxy = blurred(xy, w, h);
  constexpr double kC1 = (0.01 * 255.0) * (0.01 * 255.0);
  constexpr double kC2 = (0.03 * 255.0) * (0.03 * 255.0);
  double sum = 0.0;
  double weight_sum = 0.0;
  for (std::size_t p = 0; p < x.size(); ++p) {
    const double weight = weights.empty() ? 1.0 : weights[p];
    if (weight <= 0.0) {
      continue;
    }
    const double var_x = sxx[p] - mx[p] * mx[p];
    const double var_y = syy[p] - my[p] * my[p];
    const double cov = sxy[p] - mx[p] * my[p];
    const double ssim = ((2.0 * mx[p] * my[p] + kC1) * (2.0 * cov + kC2)) /
                        ((mx[p] * mx[p] + my[p] * my[p] + kC1) * (var_x + var_y + kC2));
    sum += weight * ssim;
    weight_sum += weight;
  }
  return weight_sum > 0.0 ? sum / weight_sum : 1.0;
}

ImageComparison compare_images(const Image& actual, const Image& expected,
                               const ImageTolerance& tolerance, const std::vector<float>& weights) {
  ImageComparison result;
  result.same_size = actual.width == expected.width && actual.height == expected.height;
  if (!result.same_size) {
    result.differing_fraction = 1.0;
    result.mean_error = 255.0;
    result.ssim = 0.0;
    result.difference = actual;
    return result;
  }
  const std::size_t pixels = static_cast<std::size_t>(actual.width) * actual.height;
  const int shift = std::max(tolerance.shift, 0);
  const ChannelRange around_expected = neighbourhood_range(expected, shift);
  const ChannelRange around_actual = neighbourhood_range(actual, shift);
  result.difference = Image(actual.width, actual.height);
  double differing = 0.0;
  double error_sum = 0.0;
  double weight_sum = 0.0;
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::uint8_t* a = actual.rgba.data() + 4 * p;
    const std::uint8_t* e = expected.rgba.data() + 4 * p;
    const double weight = weights.empty() ? 1.0 : weights[p];
    std::uint8_t* out = result.difference.rgba.data() + 4 * p;
    out[3] = 255;
    if (weight <= 0.0) {
      out[0] = out[1] = 30;
      out[2] = 90;
      continue;
    }
    weight_sum += weight;
    for (int c = 0; c < 3; ++c) {
      error_sum += weight * std::abs(int{a[c]} - int{e[c]});
    }
    const bool differs =
        outside(a, &around_expected.low[3 * p], &around_expected.high[3 * p],
                tolerance.threshold) ||
        outside(e, &around_actual.low[3 * p], &around_actual.high[3 * p], tolerance.threshold);
    if (differs) {
      differing += weight;
      out[0] = 255;
      out[1] = 0;
      out[2] = 0;
    } else {
      const auto grey = static_cast<std::uint8_t>((a[0] + a[1] + a[2]) / 6);
      out[0] = out[1] = out[2] = grey;
    }
  }
  if (weight_sum > 0.0) {
    result.differing_fraction = differing / weight_sum;
    result.mean_error = error_sum / (3.0 * weight_sum);
  }
  result.ssim = structural_similarity(actual, expected, weights);
  return result;
}

std::string ImageComparison::failures(const ImageTolerance& tolerance) const {
  if (!same_size) {
    return "the pictures differ in size";
  }
  std::string text;
  const auto add = [&](const std::string& part) { text += (text.empty() ? "" : "; ") + part; };
  if (differing_fraction > tolerance.max_differing_fraction) {
    add(fmt::format("{:.3f} % of pixels differ (allowed {:.3f} %)", 100.0 * differing_fraction,
                    100.0 * tolerance.max_differing_fraction));
  }
  if (mean_error > tolerance.max_mean_error) {
    add(fmt::format("mean error {:.3f} (allowed {:.3f})", mean_error, tolerance.max_mean_error));
  }
  if (ssim < tolerance.min_ssim) {
    add(fmt::format("SSIM {:.4f} (at least {:.4f} wanted)", ssim, tolerance.min_ssim));
  }
  return text;
}

}  // namespace dinam
