#pragma once
// The tolerances a folder of golden images is checked under, kept beside them in
// `tolerances.yaml`, so that a scene whose sky is noisy or whose thin wires jitter says so once,
// next to its goldens, instead of on every command line:
//
//   version: 1
//   default: {threshold: 24, shift: 1, max_differing: 0.005, max_mean_error: 1.0, min_ssim: 0.99}
//   scenes:
//     flag:
//       min_ssim: 0.97
//       ignore: [{pixels: [0, 0, 120, 20]}]               # a caption, in the golden's pixels
//       weigh: [{box: [[-0.1, -0.1, 0], [0.1, 0.1, 2]], weight: 4}]   # the pole, in metres
//       frames:
//         120: {max_differing: 0.01}
//
// Each level (`default`, a scene, a frame of it) may give any of the tolerance's limits
// (io/image_compare.hpp) and regions: `ignore` (left out of every measure) and `weigh` (counted
// `weight` times, default 4), each a rectangle of the picture, `pixels: [x0, y0, x1, y1]` (x1 and
// y1 excluded), or a box of the scene, `box: [[x, y, z], [x, y, z]]`, which each frame's camera
// projects to the rectangle that holds it. A frame takes its scene's limits where it gives none,
// a scene the default's; the regions of all three apply. A folder without the file checks every
// frame under the default tolerance.
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "io/image_compare.hpp"

namespace dinam {

inline constexpr const char* kToleranceFileName = "tolerances.yaml";

struct SnapshotRegion {
  std::optional<std::array<int, 4>> pixels;  // x0, y0, x1, y1
  Vec3 box_low = Vec3::Zero();               // when `pixels` is empty: the scene's box
  Vec3 box_high = Vec3::Zero();
  float weight = 0.0f;  // 0: ignored
  FileLoc loc;
};

// What one level of the file gives: the limits it sets, its regions.
struct ToleranceLevel {
  std::optional<int> threshold;
  std::optional<int> shift;
  std::optional<double> max_differing_fraction;
  std::optional<double> max_mean_error;
  std::optional<double> min_ssim;
  std::vector<SnapshotRegion> regions;
};

struct SceneTolerances {
  ToleranceLevel scene;
  std::map<int, ToleranceLevel> frames;
};

// What a frame is checked under.
struct FrameTolerance {
  ImageTolerance limits;
  std::vector<SnapshotRegion> regions;
};

struct ToleranceFile {
  std::filesystem::path path;  // where it was read from, or would be
  bool exists = false;
  ToleranceLevel defaults;
  std::map<std::string, SceneTolerances> scenes;

  // The defaults, then `scene`'s, then `frame`'s, over `base` (the command line's limits).
  FrameTolerance for_frame(const ImageTolerance& base, const std::string& scene, int frame) const;
};

// Reads `folder`/tolerances.yaml (an empty file when there is none). Throws UserError at the line
// of a bad key or value.
ToleranceFile read_tolerance_file(const std::filesystem::path& folder);

// For `--update`: writes the file with the default limits written out and an empty entry for
// each of `scenes` when the folder has none; adds an entry for each of `scenes` it lacks when it
// has one whose `scenes:` map is the last thing in it (anything else is left as it is, and the
// entry is not needed: a scene without one takes the defaults). Returns what it did, for a
// message ("" when nothing).
std::string record_scenes(const std::filesystem::path& folder,
                          const std::vector<std::string>& scenes, const ImageTolerance& limits);

}  // namespace dinam
