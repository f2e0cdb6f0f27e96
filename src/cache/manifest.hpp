#pragma once
// manifest.json, the table of contents of a motion cache: what made it (dinam's version, the
// scene's path, content hash and the settings that decide its motion), the frames (fps, count,
// each frame's bounds), the objects and their files, and the energy report when asked for. It is
// written last, so a folder with a manifest is a complete cache.
#include <filesystem>
#include <string>
#include <vector>

#include "core/look.hpp"
#include "core/types.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

// The box around one frame's node positions (all objects), in the renderer's single precision,
// and the box of its subject (core/subject_box.hpp), which the automatic camera frames.
struct FrameBounds {
  Vec3f min = Vec3f::Zero();          // m
  Vec3f max = Vec3f::Zero();          // m
  Vec3f subject_min = Vec3f::Zero();  // m
  Vec3f subject_max = Vec3f::Zero();  // m
};

// How the scene draws an object, for what shows a cache without the scene: the USD stage's prims
// and `dinam view`.
struct ObjectLook {
  bool surface = true;            // its faces drawn
  bool wires = false;             // all its bars drawn as wires, not only those on no face
  float wire_radius = 0.0f;       // m, the radius its bars are drawn with
  Vec3f color{0.8f, 0.8f, 0.8f};  // linear RGB
  // The PNG its surface wears, empty for none: in a cache request the scene's file; in the
  // manifest its copy, a file of the cache's own folder, which the USD stage and `dinam view` use.
  std::filesystem::path texture;
  Finish finish;  // how its surface takes the light (the USD stage's materials; not kept)
  // How its surface is shaded across its edges (`dinam view` draws it so).
  Shading shading = Shading::kSmooth;
  double sharp_angle = kDefaultSharpAngle;  // degrees, for Shading::kAuto
};

// One object's files, each a name inside the cache folder; pc2 or mdd is empty when that format
// was not written.
struct CacheObjectEntry {
  std::string name;
  Index first_node = 0;  // its nodes are first_node … first_node + node_count − 1 of the model
  Index node_count = 0;
  Index bar_count = 0;
  std::string obj;
  std::string pc2;
  std::string mdd;
  // Where its mesh file numbers its vertices (an OBJ's `v` lines): how many the file has, and,
  // unless its points are exactly the file's vertices in order, each point's 0-based vertex
  // number there (−1 for none): the map from the caches to the artist's own mesh.
  Index source_vertex_count = 0;  // 0: no such file
  std::vector<Index> source_vertices;
  ObjectLook look;
};

// Columns of numbers, one row per frame: the energy report of `dinam simulate --energy`.
struct EnergyTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;  // (frame_count) × (columns)
};

// A bar that broke (tearing), by its end nodes, and the first frame that shows it broken; the
// point caches hold positions only, so the tears travel in the manifest.
struct CacheTear {
  int frame = 1;
  Index n0 = 0;
  Index n1 = 0;
};

// Motion blur's instants (frame_source.hpp, shutter_offsets): every node's positions at each
// frame's instants, frame after frame, in one PC2 file of the whole model.
struct CacheInstants {
  int per_frame = 0;         // 0: the cache holds none
  double shutter = 0.0;      // fraction of the frame interval
  std::vector<int> offsets;  // (per_frame) steps from each frame's own step
  std::string pc2;           // the file, inside the cache folder
};

struct CacheManifest {
  static constexpr const char* kFormat = "dinam motion cache";
  static constexpr int kFormatVersion = 1;

  std::string dinam_version;
  std::string scene_path;    // the scene file, absolute
  std::string scene_name;    // the scene's `name`
  std::string scene_sha256;  // of the scene file's bytes
  std::vector<MotionSetting> motion_settings;
  std::string created;  // UTC, ISO 8601

  double fps = 0.0;
  int frame_count = 0;    // samples in every point cache: frame k (1-based) at t = (k − 1)/fps
  double timestep = 0.0;  // s
  int steps_per_frame = 0;
  double simulate_seconds = 0.0;  // wall time
  Index node_count = 0;
  std::vector<CacheObjectEntry> objects;
  std::vector<FrameBounds> frame_bounds;  // (frame_count)
  EnergyTable energy;                     // empty unless asked for
  std::vector<CacheTear> tears;           // in the order they broke; none unless it tears
  CacheInstants instants;                 // for motion blur; none unless the scene blurs
  std::string usd;  // the USD stage of every object (usd_stage.hpp), in the folder; "" for none
};

// The path a manifest records for a scene file: absolute, with links and dots resolved.
std::string canonical_scene_path(const std::filesystem::path& scene);

// Writes the manifest as JSON. Throws RuntimeError when it cannot.
void write_manifest(const std::filesystem::path& path, const CacheManifest& manifest);

// Reads a manifest. Throws UserError naming the file when it is missing, is not JSON, or is not a
// dinam cache manifest of this format version.
CacheManifest read_manifest(const std::filesystem::path& path);

// The same from the manifest's text; `path` names it in messages. Any bytes are refused with a
// UserError or read (tests/fuzz/cache_manifest_fuzz.cpp).
CacheManifest parse_manifest(const std::string& text, const std::filesystem::path& path);

}  // namespace dinam
