// `dinam render --preview`: the look of a scene in seconds. Draft quality (one sample, hard
// shadows, no motion blur), 320 pixels wide, about 30 frames spread over the motion; drawn into an
// animated GIF that plays in real time and a contact sheet of the same frames, side by side in
// rows, each numbered. The motion is the scene's whole, simulated as render simulates it (or read
// from --cache).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "app/render_input.hpp"
#include "core/counted.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"
#include "io/movie_encoder.hpp"
#include "io/png_file.hpp"
#include "render/digit_label.hpp"
#include "render/osmesa_renderer.hpp"
#include "run/progress.hpp"
#include "visual/draw_list_from_model.hpp"
#include "visual/frame_cameras.hpp"
#include "visual/frame_drawing.hpp"
#include "visual/shot.hpp"

namespace dinam {
namespace {

constexpr int kPreviewWidth = 320;
constexpr int kPreviewFrames = 30;  // about: every Nth frame of the range, N the least that fits
constexpr int kSheetColumns = 6;
constexpr int kSheetGap = 2;  // pixels between the sheet's pictures
// Each picture's frame number, in a band below it: digits of 2 × 2 pixels, 14 high, 3 apart from
// the picture and from the next row.
constexpr int kLabelScale = 2;
constexpr int kLabelPad = 3;
constexpr unsigned char kLabelColor[3] = {210, 210, 210};

int label_band() {
  return digit_label_height(kLabelScale) + 2 * kLabelPad;
}

void draft_at_preview_size(SceneDescription& scene) {
  scene.quality = quality_preset(QualityPreset::kDraft);
  const double aspect = static_cast<double>(scene.image_height) / scene.image_width;
  scene.image_height = std::max(2, 2 * static_cast<int>(std::lround(0.5 * kPreviewWidth * aspect)));
  scene.image_width = kPreviewWidth;
}

// The pictures in rows of kSheetColumns on a dark grey, frame order left to right, each with its
// frame number below it, so that a shot can be picked from the sheet.
Image contact_sheet(const std::vector<Image>& pictures, const std::vector<int>& frames) {
  const int w = pictures.front().width;
  const int h = pictures.front().height;
  const int cell = h + label_band();
  const int columns = std::min(kSheetColumns, static_cast<int>(pictures.size()));
  const int rows = (static_cast<int>(pictures.size()) + columns - 1) / columns;
  Image sheet(columns * w + (columns + 1) * kSheetGap, rows * cell + (rows + 1) * kSheetGap);
  for (std::size_t k = 0; k < sheet.rgba.size(); k += 4) {
    sheet.rgba[k] = sheet.rgba[k + 1] = sheet.rgba[k + 2] = 40;
    sheet.rgba[k + 3] = 255;
  }
  for (std::size_t p = 0; p < pictures.size(); ++p) {
    const int x0 = kSheetGap + static_cast<int>(p % columns) * (w + kSheetGap);
    const int y0 = kSheetGap + static_cast<int>(p / columns) * (cell + kSheetGap);
    for (int y = 0; y < h; ++y) {
      std::copy_n(
          pictures[p].pixel(0, y), 4 * w,
          sheet.rgba.begin() + 4 * (static_cast<std::ptrdiff_t>(y0 + y) * sheet.width + x0));
    }
    draw_digit_label(sheet, x0 + kLabelPad, y0 + h + kLabelPad, std::to_string(frames[p]),
                     kLabelScale, kLabelColor);
  }
  return sheet;
}

// "every frame", "every 2nd frame", "every 11th frame".
std::string every_nth(int n) {
  if (n == 1) {
    return "every frame";
  }
  const int last = n % 10;
  const bool teen = n % 100 >= 11 && n % 100 <= 13;
  const char* suffix = teen ? "th" : last == 1 ? "st" : last == 2 ? "nd" : last == 3 ? "rd" : "th";
  return fmt::format("every {}{} frame", n, suffix);
}

}  // namespace

int run_preview(const RenderOptions& options) {
  if (options.energy_csv) {
    throw_user_error({}, "--preview draws a look, not a report; leave out --energy");
  }
  const auto start = Clock::now();
  RenderInput input = read_render_input(options, draft_at_preview_size);
  const SceneDescription& scene = input.scene;
  const FrameRange& range = input.range;
  const int every = std::max(1, (range.count() + kPreviewFrames - 1) / kPreviewFrames);
  const std::filesystem::path folder = options.output.value_or(scene.output);
  create_folder(folder);
  const std::filesystem::path gif = folder / (scene.name + "_preview.gif");
  const std::filesystem::path sheet = folder / (scene.name + "_preview.png");
  check_output_name(gif);
  check_output_name(sheet);
  const StopOnSignals stop_on_signals;

  const SimulatedFrames frames = render_motion(input, options.quiet, nullptr);
  const Shot shot = make_shot(scene, input.model, frames, input.textures);
  const DrawList& draw_list = shot.draw_list;
  const FrameCameras& cameras = shot.cameras;
  OsmesaRenderer renderer(render_settings(scene));
  std::vector<Image> pictures;
  std::vector<int> drawn;  // each picture's frame
  Progress progress((range.count() + every - 1) / every, !options.quiet, "draw");
  for (int frame = range.first; frame <= range.last; frame += every) {
    draw_frames(renderer, draw_list, frames, cameras, frame, frame, [&](int, const Image& image) {
      stop_if_asked();
      pictures.push_back(image);
      drawn.push_back(frame);
      progress.update(static_cast<int>(pictures.size()), "");
    });
  }
  progress.finish();

  write_png(sheet, contact_sheet(pictures, drawn));
  std::string made = sheet.string();
  // The GIF plays at the scene's pace: every Nth frame, each shown N frames long.
  const std::unique_ptr<MovieEncoder> movie = MovieEncoder::start(
      {scene.image_width, scene.image_height, scene.fps / every, gif, true, stop_if_asked});
  if (movie) {
    for (const Image& picture : pictures) {
      movie->add_frame(picture);
    }
    movie->finish();
    made = fmt::format("{} and {}", gif.string(), made);
  } else {
    fmt::print(stderr,
               "dinam: ffmpeg was not found, so no GIF was made; install it with: sudo "
               "apt-get install ffmpeg\n");
  }
  if (!options.quiet) {
    fmt::print("dinam: preview of {} ({}) in {} ({:.1f} s)\n",
               counted(static_cast<long long>(pictures.size()), "frame"), every_nth(every), made,
               seconds_since(start));
  }
  return movie ? kExitOk : kExitFailure;
}

}  // namespace dinam
