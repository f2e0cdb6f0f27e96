#pragma once
// Scenes the benchmarks share beside the shipped ones.
#include <filesystem>
#include <string>

#include "scene/scene_description.hpp"

namespace dinam {

// About 100 000 bars: a 180 × 180 grid with one diagonal per cell (32 761 nodes, 97 560 bars,
// 98 277 bending springs), hung from one edge; with torsion, 97 560 torsion springs more.
// `contact` is the scene's `contact` map, or empty for none.
inline SceneDescription large_flag_scene(bool torsion = false, const std::string& contact = "") {
  const std::string contact_line = contact.empty() ? "" : "contact: " + contact + "\n";
  return read_scene_text("version: 1\nduration: 1\n" + contact_line + R"(objects:
  - name: cloth
    mesh:
      grid: {width: 3.6, height: 3.6, columns: 180, rows: 180, diagonals: one}
      rotation: [90, 0, 0]
      translation: [0, 0, 1.0]
    material: {density: 1200, youngs_modulus: 5.0e6, radius: 0.001}
    pinned: {box: {min: [-0.01, -0.01, 0], max: [0.01, 0.01, 5]}}
    torsion: )" + (torsion ? "true" : "false") + "\n",
                         std::filesystem::path(DINAM_SOURCE_DIR) / "scenes/large_flag.yaml");
}

}  // namespace dinam
