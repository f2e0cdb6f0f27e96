#include "run/energy_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

namespace dinam {

namespace {

constexpr double kWidth = 960.0;  // px, the picture
constexpr double kHeight = 540.0;
constexpr double kLeft = 80.0;  // px, the plot's margins: room for the axes' numbers, the legend
constexpr double kRight = 220.0;
constexpr double kTop = 50.0;
constexpr double kBottom = 50.0;

// A colour for each account after the time (kEnergyColumns' order), the total in black.
constexpr std::array<const char*, kEnergyColumns.size()> kColors = {
    "",        "#d62728", "#1f77b4", "#2ca02c", "#17becf", "#8c564b", "#9467bd", "#ff7f0e",
    "#e377c2", "#bcbd22", "#7f7f7f", "#aec7e8", "#98df8a", "#c5b0d5", "#ffbb78", "#000000"};

// "kinetic_J" → "kinetic".
std::string_view label_of(std::string_view column) {
  return column.substr(0, column.size() - 2);
}

}  // namespace

void write_energy_plot(OutputFile& file,
                       const std::vector<std::array<double, kEnergyColumns.size()>>& rows) {
  constexpr std::size_t kTotal = kEnergyColumns.size() - 1;
  double t0 = rows.empty() ? 0.0 : rows.front()[0];
  double t1 = rows.empty() ? 1.0 : rows.back()[0];
  if (!(t1 > t0)) {
    t1 = t0 + 1.0;
  }
  double low = 0.0;
  double high = 0.0;
  double peak_kinetic = 0.0;
  double worst = 0.0;
  std::array<bool, kEnergyColumns.size()> shown{};
  for (const auto& row : rows) {
    for (std::size_t c = 1; c < row.size(); ++c) {
      shown[c] = shown[c] || row[c] != 0.0;
      low = std::min(low, row[c]);
      high = std::max(high, row[c]);
    }
    peak_kinetic = std::max(peak_kinetic, row[1]);
    worst = std::max(worst, std::abs(row[kTotal] - rows.front()[kTotal]));
  }
  if (!(high > low)) {
    high = low + 1.0;
  }
  const double plot_width = kWidth - kLeft - kRight;
  const double plot_height = kHeight - kTop - kBottom;
  auto x_of = [&](double t) { return kLeft + plot_width * (t - t0) / (t1 - t0); };
  auto y_of = [&](double e) { return kTop + plot_height * (high - e) / (high - low); };

  std::FILE* out = file.stream();
  fmt::print(out,
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
             "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"13\">\n"
             "<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n",
             kWidth, kHeight);
  const std::string balance =
      peak_kinetic > 0.0
          ? fmt::format("balance within {:.3g} % of the peak kinetic energy ({:.4g} J)",
                        100.0 * worst / peak_kinetic, peak_kinetic)
          : fmt::format("balance within {:.4g} J", worst);
  fmt::print(out, "<text x=\"{}\" y=\"28\" font-size=\"16\">Energy against time: {}</text>\n",
             kLeft, balance);
  // The axes, with the ends of each range and zero.
  fmt::print(out,
             "<g stroke=\"#444\" fill=\"none\"><rect x=\"{}\" y=\"{}\" width=\"{}\" "
             "height=\"{}\"/></g>\n",
             kLeft, kTop, plot_width, plot_height);
  for (const double e : {low, 0.0, high}) {
    fmt::print(out,
               "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.2f}\" y2=\"{2:.2f}\" stroke=\"#ddd\"/>"
               "<text x=\"{3}\" y=\"{4:.2f}\" text-anchor=\"end\">{5:.4g} J</text>\n",
               kLeft, kLeft + plot_width, y_of(e), kLeft - 6.0, y_of(e) + 4.0, e);
  }
  for (const double t : {t0, t1}) {
    fmt::print(out, "<text x=\"{:.2f}\" y=\"{}\" text-anchor=\"middle\">{:.3g} s</text>\n", x_of(t),
               kHeight - kBottom + 20.0, t);
  }
  // One line an account, the legend beside the plot.
  double legend_y = kTop + 10.0;
  for (std::size_t c = 1; c < kEnergyColumns.size(); ++c) {
    if (!shown[c]) {
      continue;
    }
    fmt::print(out, "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" points=\"",
               kColors[c], c == kTotal ? 2.5 : 1.5);
    for (const auto& row : rows) {
      fmt::print(out, "{:.2f},{:.2f} ", x_of(row[0]), y_of(row[c]));
    }
    fmt::print(out, "\"/>\n");
    fmt::print(out,
               "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"{3}\" "
               "stroke-width=\"2.5\"/><text x=\"{4}\" y=\"{5}\">{6}</text>\n",
               kWidth - kRight + 15.0, kWidth - kRight + 40.0, legend_y, kColors[c],
               kWidth - kRight + 46.0, legend_y + 4.0, label_of(kEnergyColumns[c]));
    legend_y += 20.0;
  }
  fmt::print(out, "</svg>\n");
  file.commit();
}

}  // namespace dinam
