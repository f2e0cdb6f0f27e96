#pragma once
// The scene readers that more than one file of the scene stage uses: scene_reader.cpp reads the
// scene's top level and its forces, object_reader.cpp its objects, material_reader.cpp and
// mesh_reader.cpp their materials and meshes. Each reader takes a YamlMap,
// reads every key it knows and finishes the map (docs/scene-format.md documents every key).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {

// Throws a UserError at `loc` naming `what` unless value > 0.
void require_positive(double value, const FileLoc& loc, const std::string& what, const char* unit);

// A material value within the range docs/scene-format.md gives: beyond it no real material lies,
// and the masses, stiffnesses and the stable step derived from it leave double precision.
void require_in_range(double value, double low, double high, const FileLoc& loc,
                      const std::string& what, const char* unit);

// An object's `material`: density, stiffness, section, yield and breaking, with the values derived
// from them (section properties from the radius, yield moments from the yield stress).
MaterialDesc read_material(YamlMap map);

// One entry of an object's `parts`: which bars (exactly one of `nodes`, `mesh_material`,
// `mesh_group`, the names from `mesh`) and their `material`.
MaterialPartDesc read_material_part(YamlMap part, const RawMesh& mesh);

// An object's `mesh`: exactly one of `file`, `grid` or `polyline`, then the units and placement.
// Fills the object's mesh, in world space, and its `weld`.
void read_mesh(YamlMap map, const std::filesystem::path& scene_folder, ObjectDesc& object,
               std::vector<std::string>& warnings);

// A time profile: constant, step, ramp or sine.
TimeProfile read_profile(YamlMap map);

// A colour as artists pick it at `key`: [r, g, b] in sRGB, decoded to linear light, or
// {linear: [r, g, b]} as it is; linear RGB.
Vec3f read_color(YamlMap& map, const std::string& key);

// A set of an object's vertices: `all`, `indices`, `box` (one or a list). Indices are `mesh`'s
// vertex ids, but for an OBJ file the numbers of its `v` lines (from 0), turned into `mesh`'s ids
// here. Where `clamped` is given, the map may also hold `clamped: true/false` (pinned sets), which
// it receives.
NodeSelection read_nodes(YamlMap map, const RawMesh& mesh, bool* clamped = nullptr);

// `friction: {static, kinetic}` (and, where `stick` is given, `stick: true/false`): the
// coefficients must be ≥ 0 and kinetic ≤ static; kinetic defaults to the lesser of its default and
// static.
void read_friction(YamlMap map, double& static_friction, double& kinetic_friction,
                   bool* stick = nullptr);

// The scene's `contact` map, and an object's (`contact: {objects, self, radius}`).
ContactDesc read_contact(YamlMap map);
ObjectContactDesc read_object_contact(YamlMap map);

// An object's `attach` list (attachment_reader.cpp): its nodes tied to other objects.
std::vector<AttachmentDesc> read_attachments(YamlMap& object_map, const ObjectDesc& object);

// The scene's `camera` (a map, or `auto`); what is allowed but implausible goes to `warnings`.
CameraDesc read_camera(const YAML::Node& node, const std::string& file,
                       std::vector<std::string>& warnings);

// The scene's `image` map: size, quality preset and the features it sets; into `scene`.
void read_image(YamlMap map, SceneDescription& scene);

// An object's `finish`: a preset name or {roughness, metallic, sheen}.
Finish read_finish(const YAML::Node& node, const std::string& file, const std::string& what);

// One entry of `objects`, its mesh loaded; `frames` is the scene's duration × fps (a point cache
// is read as far as the run reaches).
ObjectDesc read_object(YamlMap map, int index, const std::filesystem::path& scene_folder,
                       double frames, std::vector<std::string>& warnings);

}  // namespace dinam
