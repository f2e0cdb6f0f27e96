#include "snapshot/snapshot_report.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/base64.hpp"
#include "core/output_file.hpp"
#include "io/png_file.hpp"

namespace dinam {
namespace {

// Text as XML and HTML take it inside elements and quoted attributes.
std::string escaped(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

const char* outcome_text(FrameOutcome outcome) {
  switch (outcome) {
    case FrameOutcome::kMatched:
      return "matches";
    case FrameOutcome::kDiffers:
      return "differs";
    case FrameOutcome::kNoGolden:
      return "no golden";
    case FrameOutcome::kUpdated:
      return "updated";
  }
  return "";
}

// The scenes in the order they were run, each with its frames' results.
std::vector<std::pair<std::string, std::vector<const FrameResult*>>> by_scene(
    const std::vector<FrameResult>& results) {
  std::vector<std::pair<std::string, std::vector<const FrameResult*>>> scenes;
  for (const FrameResult& result : results) {
    if (scenes.empty() || scenes.back().first != result.scene) {
      scenes.push_back({result.scene, {}});
    }
    scenes.back().second.push_back(&result);
  }
  return scenes;
}

std::string figures(const FrameResult& r) {
  const ImageComparison& c = r.comparison;
  return fmt::format(
      "{:.3f} % of pixels differ (allowed {:.3f} %), mean error {:.3f} (allowed {:.3f}), SSIM "
      "{:.4f} (at least {:.4f})",
      100.0 * c.differing_fraction, 100.0 * r.limits.max_differing_fraction, c.mean_error,
      r.limits.max_mean_error, c.ssim, r.limits.min_ssim);
}

std::string picture(const Image& image, const char* label) {
  if (image.width == 0) {
    return fmt::format("<figure><div class=\"none\">none</div><figcaption>{}</figcaption></figure>",
                       label);
  }
  const std::string png = png_bytes(image, PngOptions{6, true});
  return fmt::format(
      "<figure><img alt=\"{0}\" width=\"{1}\" height=\"{2}\" "
      "src=\"data:image/png;base64,{3}\"><figcaption>{0}</figcaption></figure>",
      label, image.width, image.height, base64(png.data(), png.size()));
}

std::string measure_row(const char* name, const std::string& value, const std::string& limit,
                        bool within) {
  return fmt::format("<tr class=\"{}\"><td>{}</td><td>{}</td><td>{}</td></tr>",
                     within ? "ok" : "bad", name, value, limit);
}

}  // namespace

bool failed(const FrameResult& result) {
  return result.outcome == FrameOutcome::kDiffers || result.outcome == FrameOutcome::kNoGolden ||
         !result.framing_problem.empty();
}

void write_junit_report(const std::filesystem::path& path,
                        const std::vector<FrameResult>& results) {
  const auto count_failed = [](const auto& list) {
    return std::count_if(list.begin(), list.end(), [](const auto& r) { return failed(*r); });
  };
  std::vector<const FrameResult*> all;
  double total_seconds = 0.0;
  for (const FrameResult& r : results) {
    all.push_back(&r);
    total_seconds += r.seconds;
  }
  std::string xml = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<testsuites name=\"dinam snapshot\" tests=\"{}\" failures=\"{}\" errors=\"0\" "
      "time=\"{:.3f}\">\n",
      results.size(), count_failed(all), total_seconds);
  for (const auto& [scene, frames] : by_scene(results)) {
    double seconds = 0.0;
    for (const FrameResult* r : frames) {
      seconds += r->seconds;
    }
    xml += fmt::format(
        "  <testsuite name=\"snapshot.{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" "
        "time=\"{:.3f}\">\n",
        escaped(scene), frames.size(), count_failed(frames), seconds);
    for (const FrameResult* r : frames) {
      xml += fmt::format(
          "    <testcase classname=\"snapshot.{}\" name=\"frame {:04}\" "
          "time=\"{:.3f}\"",
          escaped(scene), r->frame, r->seconds);
      if (!failed(*r)) {
        xml += fmt::format(">\n      <system-out>{}: {}</system-out>\n    </testcase>\n",
                           outcome_text(r->outcome),
                           escaped(r->outcome == FrameOutcome::kUpdated ? r->detail : figures(*r)));
        continue;
      }
      xml += fmt::format(
          ">\n      <failure type=\"{}\" message=\"{}\">{}</failure>\n    </testcase>\n",
          outcome_text(r->outcome), escaped(r->detail),
          escaped(r->outcome == FrameOutcome::kDiffers ? figures(*r) : r->detail));
    }
    xml += "  </testsuite>\n";
  }
  xml += "</testsuites>\n";
  write_output_file(path, xml, "the JUnit report");
}

void write_html_report(const std::filesystem::path& path, const std::vector<FrameResult>& results) {
  const auto failures =
      std::count_if(results.begin(), results.end(), [](const FrameResult& r) { return failed(r); });
  std::string html = fmt::format(
      R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>dinam snapshot: {0} of {1} frames differ</title>
<style>
body {{ font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; }}
h1 {{ font-size: 1.3em; }} h2 {{ font-size: 1.1em; margin-top: 1.5em; }}
section.frame {{ border: 1px solid #ccc; border-radius: 6px; margin: 0.8em 0; padding: 0.2em 0.8em; }}
section.failed {{ border-color: #c33; background: #fff6f6; }}
.badge {{ display: inline-block; padding: 0 0.5em; border-radius: 3px; color: #fff; background: #397; }}
.failed .badge {{ background: #c33; }}
figure {{ display: inline-block; margin: 0.4em 0.8em 0.4em 0; vertical-align: top; }}
figure img {{ image-rendering: pixelated; border: 1px solid #999; max-width: 100%; }}
figcaption {{ text-align: center; color: #555; }}
div.none {{ width: 160px; height: 90px; border: 1px dashed #999; color: #999; text-align: center; line-height: 90px; }}
table {{ border-collapse: collapse; margin: 0.3em 0; }} td {{ padding: 0 0.8em 0 0; }}
tr.bad td {{ color: #c33; font-weight: bold; }}
</style></head><body>
<h1>dinam snapshot: {0} of {1} frames differ</h1>
<p>Each frame is compared with its golden under its tolerance (the folder's tolerances.yaml):
the pixels that differ beyond the threshold even allowing an edge to move, the mean channel error
and the structural similarity (SSIM). In the difference picture, red marks a differing pixel and
dark blue one left out by an <code>ignore</code> region.</p>
)",
      failures, results.size());
  // Failures first, then the rest, each in the order run.
  std::vector<const FrameResult*> order;
  for (const bool failures_first : {true, false}) {
    for (const FrameResult& r : results) {
      if (failed(r) == failures_first) {
        order.push_back(&r);
      }
    }
  }
  for (const FrameResult* r : order) {
    const ImageComparison& c = r->comparison;
    html += fmt::format("<section class=\"frame{}\"><h2>{} <span class=\"badge\">{}</span></h2>\n",
                        failed(*r) ? " failed" : "", escaped(r->name), outcome_text(r->outcome));
    if (!r->detail.empty()) {
      html += fmt::format("<p>{}</p>\n", escaped(r->detail));
    }
    if (r->outcome == FrameOutcome::kMatched || r->outcome == FrameOutcome::kDiffers) {
      html += "<table><tr><th>measure</th><th>value</th><th>limit</th></tr>";
      html +=
          measure_row("pixels that differ", fmt::format("{:.3f} %", 100.0 * c.differing_fraction),
                      fmt::format("at most {:.3f} % (threshold {}, shift {} px{})",
                                  100.0 * r->limits.max_differing_fraction, r->limits.threshold,
                                  r->limits.shift, r->has_regions ? ", regions weighed" : ""),
                      c.differing_fraction <= r->limits.max_differing_fraction);
      html += measure_row("mean error", fmt::format("{:.3f}", c.mean_error),
                          fmt::format("at most {:.3f}", r->limits.max_mean_error),
                          c.mean_error <= r->limits.max_mean_error);
      html += measure_row("SSIM", fmt::format("{:.4f}", c.ssim),
                          fmt::format("at least {:.4f}", r->limits.min_ssim),
                          c.ssim >= r->limits.min_ssim);
      if (r->framing_checked) {
        html +=
            measure_row("subject's span",
                        fmt::format("{:.0f} % × {:.0f} %", 100.0f * r->subject_width,
                                    100.0f * r->subject_height),
                        fmt::format("inside the frame, at least {:.0f} % of its width or height",
                                    100.0f * r->min_fill),
                        r->framing_problem.empty());
      }
      html += "</table>\n";
    }
    html += picture(r->expected, "expected");
    html += picture(r->actual, "actual");
    if (r->outcome == FrameOutcome::kMatched || r->outcome == FrameOutcome::kDiffers) {
      html += picture(c.difference, "difference");
    }
    html += "</section>\n";
  }
  html += "</body></html>\n";
  write_output_file(path, html, "the HTML report");
}

}  // namespace dinam
