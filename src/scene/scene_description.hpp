#pragma once
// The plain description of a scene as the file states it, validated and with meshes loaded, but
// not yet a physical model. Every value a later stage might complain about keeps its FileLoc, so
// that an error found there (an unstable step, a zero-length bar) still names file:line:column.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scene/raw_mesh.hpp"

namespace dinam {

// Section and elastic properties of the bars of one object, SI units.
struct MaterialDesc {
  double density = 0.0;         // kg/m³
  double youngs_modulus = 0.0;  // E, Pa
  double shear_modulus = 0.0;   // G, Pa
  double area = 0.0;            // A, m²
  double area_moment = 0.0;     // I, m⁴ (bending; used by the bending springs)
  double polar_moment = 0.0;    // J, m⁴ (torsion; used by the torsion springs)
  double wire_radius = 0.0;     // m, when the section was given as a circular wire; else 0
  FileLoc loc;
};

struct BoxDesc {
  Vec3 min = Vec3::Zero();  // m, world space
  Vec3 max = Vec3::Zero();
};

// Which vertices of an object are fixed in space. The union of all three choices.
struct PinDesc {
  bool all = false;
  std::vector<Index> vertex_ids;  // ids into the object's own mesh vertices
  std::vector<BoxDesc> boxes;     // vertices inside any box (inclusive)
  FileLoc loc;
};

struct ObjectDesc {
  std::string name;
  FileLoc loc;
  RawMesh mesh;  // in world space
  FileLoc mesh_loc;
  MaterialDesc material;
  PinDesc pins;
  Vec3 initial_velocity = Vec3::Zero();  // m/s
  Vec3f color{0.8f, 0.8f, 0.8f};         // linear RGB in [0, 1]
  std::optional<double> render_radius;   // m; default: the wire radius, at least a visible minimum
};

struct CameraDesc {
  Vec3 position{4.0, -6.0, 3.0};  // m
  Vec3 look_at{0.0, 0.0, 1.0};    // m
  Vec3 up = kWorldUp;
  double fov_degrees = 40.0;  // vertical field of view
};

struct GroundDesc {
  double height = 0.0;  // m; the plane z = height
  bool visible = true;
};

struct SceneDescription {
  std::filesystem::path source;  // the scene file
  int version = 1;
  std::string name;  // movie file name; default: the scene file's stem

  double duration = 0.0;           // s
  double fps = 0.0;                // frames per second
  std::optional<double> timestep;  // s; empty for `auto`
  FileLoc timestep_loc;
  Vec3 gravity{0.0, 0.0, -9.81};  // m/s²

  GroundDesc ground;
  CameraDesc camera;
  int image_width = 1280;
  int image_height = 720;
  std::filesystem::path output;  // folder for frames and the movie

  std::vector<ObjectDesc> objects;

  // Frame k (0-based) shows time k / fps; duration × fps frames in all.
  int frame_count() const;
};

// Reads and validates a scene file, loading every mesh it names. Throws UserError naming
// file:line:column for anything wrong, including keys that are never read.
SceneDescription read_scene(const std::filesystem::path& path);

// The same from text already in memory; `source` is only used in messages and to resolve paths.
SceneDescription read_scene_text(const std::string& text, const std::filesystem::path& source);

}  // namespace dinam
