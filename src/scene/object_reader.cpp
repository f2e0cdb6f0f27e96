// The reader of a scene's objects: each object's keys, its node sets (pinned and others),
// velocities and drawing; its material and parts (material_reader.cpp) and its mesh
// (mesh_reader.cpp) have files of their own. Each reads every key it knows and finishes its map;
// docs/scene-format.md documents every key read here; keep the two together.
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <system_error>

#include "core/srgb.hpp"
#include "scene/element_readers.hpp"
#include "scene/mesh_generators.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/pin_track_reader.hpp"
#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {
namespace {

BoxDesc read_box(YamlMap map) {
  BoxDesc box;
  box.min = map.required_vec3("min");
  box.max = map.required_vec3("max");
  map.finish();
  if ((box.min.array() > box.max.array()).any()) {
    throw_user_error(map.loc(), "'{}': every coordinate of 'min' must be at most that of 'max'",
                     map.name());
  }
  return box;
}

// Whether `pins` holds every vertex of the mesh: an object pinned whole (an obstacle), whose
// material then decides nothing of the motion.
bool selects_every_vertex(const NodeSelection& pins, const RawMesh& mesh) {
  std::vector<char> held(mesh.vertices.size(), 0);
  for (const Index v : pins.vertex_ids) {
    held[static_cast<std::size_t>(v)] = 1;
  }
  for (std::size_t v = 0; v < held.size(); ++v) {
    for (const BoxDesc& box : pins.boxes) {
      const Vec3& x = mesh.vertices[v];
      if ((x.array() >= box.min.array()).all() && (x.array() <= box.max.array()).all()) {
        held[v] = 1;
      }
    }
  }
  return !held.empty() && std::all_of(held.begin(), held.end(), [](char h) { return h != 0; });
}

// A collider's material where the scene gives none: a wire of its shell's radius, which is what
// its contact and its drawing read of it; its stiffness and mass act on no free node.
MaterialDesc collider_material(double shell) {
  MaterialDesc material;
  material.density = 1000.0;
  material.youngs_modulus = 1.0e9;
  material.shear_modulus = material.youngs_modulus / 2.6;
  material.wire_radius = shell;
  material.area = std::numbers::pi * shell * shell;
  material.area_moment = 0.25 * std::numbers::pi * std::pow(shell, 4);
  material.polar_moment = 2.0 * material.area_moment;
  return material;
}

// `shading` and `sharp_angle`: flat and auto surfaces are drawn as modelled, so a `subdivide`
// beside them is refused.
void read_shading(YamlMap& map, ObjectDesc& object) {
  const std::string shading = map.string("shading", "smooth");
  const std::optional<Shading> named = shading_named(shading);
  if (!named) {
    throw_user_error(map.loc("shading"),
                     "'{}' must be smooth, flat or auto (smooth but for edges sharper than "
                     "'sharp_angle'); got '{}'",
                     map.path("shading"), shading);
  }
  object.shading = *named;
  if (map.has("sharp_angle")) {
    object.sharp_angle = map.number("sharp_angle", kDefaultSharpAngle);
    if (!(object.sharp_angle > 0.0 && object.sharp_angle < 180.0) ||
        object.shading != Shading::kAuto) {
      throw_user_error(map.loc("sharp_angle"),
                       "'{}' must be between 0 and 180 degrees, beside 'shading: auto'",
                       map.path("sharp_angle"));
    }
  }
  if (object.shading != Shading::kSmooth && object.subdivide.value_or(0) > 0) {
    throw_user_error(map.loc("subdivide"),
                     "'{}': object '{}' is shaded {}, drawn as modelled; leave 'subdivide' out, "
                     "or give it 'shading: smooth'",
                     map.path("subdivide"), object.name, shading);
  }
}

}  // namespace

// A colour as artists pick it: [r, g, b] in sRGB (Blender's colour picker, Houdini, Photoshop,
// CSS), each 0 to 1, decoded to linear light for shading; or {linear: [r, g, b]}, taken as it is
// (values from a renderer's linear workflow). The model and the cache keep linear values.
Vec3f read_color(YamlMap& map, const std::string& key) {
  const YAML::Node node = map.get(key);
  const bool linear = node.IsMap();
  Vec3 color;
  if (linear) {
    YamlMap given(node, map.file(), map.path(key));
    if (!given.has("linear")) {
      given.finish();  // names a key given in its place (`srgb`: sRGB is the list form)
    }
    color = given.required_vec3("linear");
    given.finish();
  } else {
    color = map.vec3(key, Vec3::Zero());
  }
  if ((color.array() < 0.0).any() || (color.array() > 1.0).any()) {
    throw_user_error(map.loc(key),
                     "'{}' must be [r, g, b] (sRGB, as a colour picker gives it) or {{linear: "
                     "[r, g, b]}}, each between 0 and 1",
                     map.path(key));
  }
  if (!linear) {
    for (int c = 0; c < 3; ++c) {
      color[c] = srgb_to_linear(color[c]);
    }
  }
  return color.cast<float>();
}

NodeSelection read_nodes(YamlMap map, const RawMesh& mesh, bool* clamped) {
  // An OBJ file's vertices are numbered as its `v` lines (as the program that wrote it numbers
  // them); assimp's own vertices, one per face corner, are not what a user can see.
  const bool file_numbers = !mesh.source_vertex.empty();
  const std::size_t vertex_count =
      file_numbers ? static_cast<std::size_t>(mesh.source_vertex_count) : mesh.vertices.size();
  std::vector<Index> vertex_of_number;
  if (file_numbers) {
    vertex_of_number.assign(vertex_count, -1);
    for (std::size_t v = mesh.source_vertex.size(); v-- > 0;) {
      if (mesh.source_vertex[v] >= 0) {
        vertex_of_number[mesh.source_vertex[v]] = static_cast<Index>(v);
      }
    }
  }
  NodeSelection pins;
  pins.loc = map.loc();
  if (clamped != nullptr) {
    *clamped = map.boolean("clamped", false);
  }
  pins.all = map.boolean("all", false);
  const YAML::Node indices = map.get("indices");
  if (indices) {
    if (!indices.IsSequence()) {
      throw_user_error(map.loc("indices"), "'{}' must be a list of vertex indices",
                       map.path("indices"));
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
      const int id = as_int(indices[i], map.file(), fmt::format("{}[{}]", map.path("indices"), i));
      if (id < 0 || static_cast<std::size_t>(id) >= vertex_count) {
        throw_user_error(loc_of(indices[i], map.file()),
                         "vertex index {} is out of range: the mesh has {} vertices "
                         "(0 to {})",
                         id, vertex_count, vertex_count - 1);
      }
      if (file_numbers && vertex_of_number[id] < 0) {
        throw_user_error(loc_of(indices[i], map.file()),
                         "vertex {} of the mesh file is on no face or line, so it is not a node "
                         "of the structure",
                         id);
      }
      pins.vertex_ids.push_back(file_numbers ? vertex_of_number[id] : id);
    }
  }
  const YAML::Node box = map.get("box");
  if (box && box.IsSequence()) {
    for (std::size_t i = 0; i < box.size(); ++i) {
      pins.boxes.push_back(
          read_box(YamlMap(box[i], map.file(), fmt::format("{}[{}]", map.path("box"), i))));
    }
  } else if (box) {
    pins.boxes.push_back(read_box(YamlMap(box, map.file(), map.path("box"))));
  }
  map.finish();
  return pins;
}

ObjectDesc read_object(YamlMap map, int index, const std::filesystem::path& scene_folder,
                       double frames, std::vector<std::string>& warnings) {
  ObjectDesc object;
  object.loc = map.loc();
  object.name = map.string("name", fmt::format("object{}", index));
  require_plain_name(object.name, map.loc("name"), map.path("name"));
  object.mesh_loc = map.loc("mesh");
  read_mesh(YamlMap(map.required("mesh"), map.file(), map.path("mesh")), scene_folder, object,
            warnings);
  const std::string role = map.string("role", "flexible");
  if (role != "flexible" && role != "collider") {
    throw_user_error(
        map.loc("role"),
        "'{}' must be flexible (the default: it moves by its material) or collider (an "
        "obstacle held whole, moved only by 'pin_motion'); got '{}'",
        map.path("role"), role);
  }
  object.collider = role == "collider";
  if (object.collider && map.has("pinned")) {
    throw_user_error(map.loc("pinned"),
                     "'{}': object '{}' is a collider, held whole (every node pinned); leave "
                     "'pinned' out, or make it 'role: flexible' to pin some of its nodes",
                     map.path("pinned"), object.name);
  }
  if (map.has("material") || !object.collider) {
    object.material =
        read_material(YamlMap(map.required("material"), map.file(), map.path("material")));
  }
  if (object.collider) {
    object.pins.all = true;
    object.pins.loc = map.loc("role");
  } else if (map.has("pinned")) {
    object.pins = read_nodes(YamlMap(map.get("pinned"), map.file(), map.path("pinned")),
                             object.mesh, &object.pins_clamped);
    object.pins.all = object.pins.all || selects_every_vertex(object.pins, object.mesh);
  }
  if (map.has("pin_motion")) {
    YamlMap motion(map.get("pin_motion"), map.file(), map.path("pin_motion"));
    object.pin_motion.loc = motion.loc();
    if (motion.has("point_cache")) {
      read_pin_track(motion, scene_folder, frames, object, warnings);
    } else {
      object.pin_motion.displacement = motion.required_vec3("displacement");
      if (motion.has("profile")) {
        object.pin_motion.profile =
            read_profile(YamlMap(motion.get("profile"), map.file(), motion.path("profile")));
      }
    }
    motion.finish();
    if (object.pins.empty()) {
      throw_user_error(object.pin_motion.loc,
                       "'{}' moves the pinned nodes of object '{}', which has none; add 'pinned'",
                       map.path("pin_motion"), object.name);
    }
  }
  object.attachments = read_attachments(map, object);
  object.initial_velocity = map.vec3("initial_velocity", object.initial_velocity);
  if (const YAML::Node groups = map.get("velocity_groups"); groups) {
    if (!groups.IsSequence()) {
      throw_user_error(map.loc("velocity_groups"),
                       "'{}' must be a list of {{nodes: ..., velocity: [x, y, z]}}",
                       map.path("velocity_groups"));
    }
    for (std::size_t i = 0; i < groups.size(); ++i) {
      YamlMap group(groups[i], map.file(), fmt::format("{}[{}]", map.path("velocity_groups"), i));
      VelocityGroupDesc desc;
      desc.nodes = read_nodes(YamlMap(group.required("nodes"), map.file(), group.path("nodes")),
                              object.mesh);
      desc.velocity = group.required_vec3("velocity");
      group.finish();
      object.velocity_groups.push_back(std::move(desc));
    }
  }
  if (const YAML::Node parts = map.get("parts"); parts) {
    if (!parts.IsSequence()) {
      throw_user_error(map.loc("parts"),
                       "'{}' must be a list of {{nodes | mesh_material | mesh_group: ..., "
                       "material: ...}}",
                       map.path("parts"));
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
      object.parts.push_back(read_material_part(
          YamlMap(parts[i], map.file(), fmt::format("{}[{}]", map.path("parts"), i)), object.mesh));
    }
  }
  const std::string pairs = map.string("bending_pairs", "auto");
  if (pairs == "auto") {
    object.bending_pairs = BendingPairs::kAuto;
  } else if (pairs == "collinear") {
    object.bending_pairs = BendingPairs::kMostCollinear;
  } else if (pairs == "all") {
    object.bending_pairs = BendingPairs::kAll;
  } else if (pairs == "none") {
    object.bending_pairs = BendingPairs::kNone;
  } else {
    throw_user_error(map.loc("bending_pairs"),
                     "'{}' must be auto, collinear, all or none; got '{}'",
                     map.path("bending_pairs"), pairs);
  }
  if (map.has("faces")) {
    object.faces_loc = map.loc("faces");
    const std::string faces = map.string("faces", "sheet");
    if (faces == "sheet") {
      object.faces = FaceRole::kSheet;
    } else if (faces == "net") {
      object.faces = FaceRole::kNet;
    } else {
      throw_user_error(map.loc("faces"),
                       "'{}' must be sheet (the faces are cloth: they resist shear) or net (they "
                       "are the openings between wires: the bars alone act); got '{}'",
                       map.path("faces"), faces);
    }
    if (object.faces == FaceRole::kNet && object.material.sheet) {
      throw_user_error(map.loc("faces"),
                       "'{}': object '{}' has a sheet material, whose stiffness and mass are its "
                       "faces'; a net needs a wire material (density, youngs_modulus, radius)",
                       map.path("faces"), object.name);
    }
  }
  object.torsion = map.boolean("torsion", object.torsion);
  if (map.has("contact")) {
    object.contact =
        read_object_contact(YamlMap(map.get("contact"), map.file(), map.path("contact")));
  }
  if (object.collider && !map.has("material")) {
    object.material = collider_material(object.contact.radius.value_or(kColliderShell));
    object.material.loc = map.loc("role");
  }
  if (map.has("damping")) {
    YamlMap damping(map.get("damping"), map.file(), map.path("damping"));
    if (damping.has("global")) {
      throw_user_error(damping.loc("global"),
                       "'{}': global damping is the whole scene's, a top-level 'damping: {{global: "
                       "…}}'; an object's damping takes 'axial' (N·s/m) or 'axial_ratio'",
                       damping.path("global"));
    }
    if (damping.has("axial") && damping.has("axial_ratio")) {
      throw_user_error(damping.loc(), "'{}': give 'axial' (N·s/m) or 'axial_ratio', not both",
                       damping.name());
    }
    object.axial_damping.coefficient = damping.number("axial", 0.0);
    object.axial_damping.ratio = damping.number("axial_ratio", 0.0);
    if (object.axial_damping.coefficient < 0.0 || object.axial_damping.ratio < 0.0) {
      throw_user_error(damping.loc(), "'{}': damping cannot be negative", damping.name());
    }
    damping.finish();
  }
  if (map.has("color")) {
    object.color = read_color(map, "color");
  }
  if (map.has("finish")) {
    object.finish = read_finish(map.get("finish"), map.file(), map.path("finish"));
  }
  const std::string style = map.string("style", object.mesh.faces.empty() ? "wire" : "surface");
  if (style == "surface") {
    object.style = DrawStyle::kSurface;
  } else if (style == "wire") {
    object.style = DrawStyle::kWire;
  } else if (style == "both") {
    object.style = DrawStyle::kBoth;
  } else {
    throw_user_error(map.loc("style"), "'{}' must be surface, wire or both; got '{}'",
                     map.path("style"), style);
  }
  if (object.style != DrawStyle::kWire && object.mesh.faces.empty()) {
    throw_user_error(map.loc("style"), "'{}': object '{}' has no faces to draw as a surface",
                     map.path("style"), object.name);
  }
  object.joints = map.boolean("joints", object.joints);
  if (map.has("subdivide")) {
    const int levels = map.integer("subdivide", 0);
    if (levels < 0 || levels > 3) {
      throw_user_error(map.loc("subdivide"),
                       "'{}' must be 0 (drawn as simulated) to 3 levels of smoothing; got {}",
                       map.path("subdivide"), levels);
    }
    if (object.style == DrawStyle::kWire && levels > 0) {
      throw_user_error(map.loc("subdivide"),
                       "'{}': object '{}' is drawn as wires, which have no surface to smooth; "
                       "give it 'style: surface' or 'both', or leave 'subdivide' out",
                       map.path("subdivide"), object.name);
    }
    object.subdivide = levels;
  }
  read_shading(map, object);
  if (!map.has("texture") && !object.mesh.texture.empty()) {
    object.texture = object.mesh.texture;  // the mesh file's own material
    object.texture_loc = object.mesh_loc;
  }
  if (map.has("texture")) {
    const std::filesystem::path texture = map.string("texture", "");
    object.texture = texture.is_absolute() ? texture : scene_folder / texture;
    object.texture_loc = map.loc("texture");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(object.texture, ec)) {
      throw_user_error(map.loc("texture"),
                       "texture file '{}' not found; paths are relative to the scene file's folder",
                       object.texture.string());
    }
    // Only PNG is read: check its signature now, so a wrong file is a scene error at this line.
    std::ifstream in(object.texture, std::ios::binary);
    std::array<char, 8> signature{};
    in.read(signature.data(), signature.size());
    if (!in || std::memcmp(signature.data(), "\x89PNG\r\n\x1a\n", 8) != 0) {
      throw_user_error(map.loc("texture"), "texture file '{}' is not a PNG image",
                       object.texture.string());
    }
  }
  if (map.has("render_radius")) {
    object.render_radius = map.number("render_radius", 0.0);
    require_positive(*object.render_radius, map.loc("render_radius"), map.path("render_radius"),
                     "m");
  }
  map.finish();
  return object;
}

}  // namespace dinam
