#pragma once
// Scenes the benchmarks share beside the shipped ones.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "scene/scene_description.hpp"

namespace dinam {

// Debian's assimp-testmodels: the Wuson of issues 29 and 33, as the real-mesh sweep drops it (a
// 1 m rubber wire, 0.5 m above the ground; tests/real_meshes/real_mesh_sweep.py).
constexpr const char* kWuson = "/usr/share/assimp/models/OFF/Wuson.off";

inline SceneDescription wuson_scene() {
  return read_scene_text(fmt::format(R"(version: 1
duration: 3
fps: 20
objects:
  - mesh: {{file: "{}", fit: {{size: 1}}, translation: [0, 0, 0.5]}}
    material: {{density: 1100, youngs_modulus: 5.0e7, radius: 0.004}}
    style: wire
)",
                                     kWuson),
                         std::filesystem::temp_directory_path() / "bench_wuson.yaml");
}

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
    torsion: )" + (torsion ? "true" : "false") +
                             "\n",
                         std::filesystem::path(DINAM_SOURCE_DIR) / "scenes/large_flag.yaml");
}

// The two structures of the scale sweep (bench/scale_sweep.cpp), each a 3.6 m square hung from
// its top edge, seen from a fixed camera:
//   kCloth: a grid with one diagonal a cell (about 3 n² bars for n × n cells), bending springs,
//     drawn as cloth;
//   kWireLattice: a square grid (about 2 n² bars), bending and torsion springs, drawn as wires
//     of a tenth of the spacing.
enum class ScaleStructure { kCloth, kWireLattice };

// The structure with about `bars` bars.
inline SceneDescription scale_scene(ScaleStructure structure, Index bars) {
  const bool cloth = structure == ScaleStructure::kCloth;
  const int cells = static_cast<int>(std::lround(std::sqrt(bars / (cloth ? 3.0 : 2.0))));
  const double spacing = 3.6 / cells;
  const std::string text = fmt::format(
      R"(version: 1
duration: 1
camera: {{position: [2.6, -5.2, 3.4], look_at: [0, 0, 2.0], fov: 40}}
objects:
  - name: {}
    mesh:
      grid: {{width: 3.6, height: 3.6, columns: {}, rows: {}, diagonals: {}}}
      rotation: [90, 0, 0]
      translation: [-1.8, 0, 0.2]
    material: {{density: 1200, youngs_modulus: 5.0e6, radius: {}}}
    pinned: {{box: {{min: [-2, -0.01, 3.79], max: [2, 0.01, 3.81]}}}}
    torsion: {}
    style: {}
)",
      cloth ? "cloth" : "lattice", cells, cells, cloth ? "one" : "none",
      cloth ? 0.001 : 0.1 * spacing, cloth ? "false" : "true", cloth ? "surface" : "wire");
  return read_scene_text(text, std::filesystem::temp_directory_path() / "scale_sweep.yaml");
}

}  // namespace dinam
