#include "cache/manifest.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/regular_file.hpp"

namespace dinam {
namespace {

// Keys keep the order they are written in, so the file reads top-down like this struct.
using Json = nlohmann::ordered_json;

// A frame's box and its subject's: 12 numbers (a cache from before the subject had only the box's
// 6, and its subject is the whole box).
Json bounds_json(const FrameBounds& b) {
  Json j = Json::array();
  for (const Vec3f* corner : {&b.min, &b.max, &b.subject_min, &b.subject_max}) {
    for (int c = 0; c < 3; ++c) {
      j.push_back((*corner)[c]);
    }
  }
  return j;
}

FrameBounds bounds_from(const Json& j) {
  // Floats go to JSON as doubles, which print exactly, and come back to the same float.
  FrameBounds b;
  const bool has_subject = j.size() >= 12;
  for (int c = 0; c < 3; ++c) {
    const auto at = static_cast<std::size_t>(c);
    b.min[c] = j.at(at).get<float>();
    b.max[c] = j.at(at + 3).get<float>();
    b.subject_min[c] = has_subject ? j.at(at + 6).get<float>() : b.min[c];
    b.subject_max[c] = has_subject ? j.at(at + 9).get<float>() : b.max[c];
  }
  return b;
}

// An integer of the manifest, as a whole number within the type's range: JSON's 1e20 or 2.5
// where a count belongs is refused (converting it would be undefined behaviour, not an error).
template <class T>
T integer(const Json& value) {
  if (!value.is_number_integer()) {
    throw std::invalid_argument(fmt::format("{} where a whole number belongs", value.dump()));
  }
  const auto wide = value.get<std::int64_t>();
  if (value.is_number_unsigned() && value.get<std::uint64_t>() > std::uint64_t{INT64_MAX}) {
    throw std::invalid_argument(fmt::format("{} is out of range", value.dump()));
  }
  if (wide < std::numeric_limits<T>::min() || wide > std::numeric_limits<T>::max()) {
    throw std::invalid_argument(fmt::format("{} is out of range", value.dump()));
  }
  return static_cast<T>(wide);
}

template <class T>
std::vector<T> integers(const Json& list) {
  std::vector<T> values;
  for (const Json& value : list) {
    values.push_back(integer<T>(value));
  }
  return values;
}

// `name` (of `owner`'s `kind` file) is a plain file name in the cache's folder, or empty where
// `may_be_empty`.
void require_file_name(const FileLoc& loc, const std::string& name, const std::string& owner,
                       const char* kind, bool may_be_empty) {
  if (name.empty() ? !may_be_empty
                   : name == "." || name == ".." || name.find('/') != std::string::npos ||
                         name.find('\0') != std::string::npos) {
    throw UserError(loc, fmt::format("{}'s {} file is named '{}', which is not a file of the "
                                     "cache's own folder; the manifest was edited or damaged: "
                                     "simulate again",
                                     owner, kind, name));
  }
}

}  // namespace

std::string canonical_scene_path(const std::filesystem::path& scene) {
  std::error_code ec;
  const std::filesystem::path path = std::filesystem::weakly_canonical(scene, ec);
  return (ec ? std::filesystem::absolute(scene) : path).string();
}

void write_manifest(const std::filesystem::path& path, const CacheManifest& m) {
  Json settings = Json::object();
  for (const MotionSetting& s : m.motion_settings) {
    settings[s.key] = s.value;
  }
  Json objects = Json::array();
  for (const CacheObjectEntry& o : m.objects) {
    Json files = {{"obj", o.obj}};
    if (!o.pc2.empty()) {
      files["pc2"] = o.pc2;
    }
    if (!o.mdd.empty()) {
      files["mdd"] = o.mdd;
    }
    Json object = {{"name", o.name},
                   {"first_node", o.first_node},
                   {"node_count", o.node_count},
                   {"bar_count", o.bar_count},
                   {"files", files}};
    object["look"] = {{"surface", o.look.surface},
                      {"wires", o.look.wires},
                      {"wire_radius", o.look.wire_radius},
                      {"color", {o.look.color.x(), o.look.color.y(), o.look.color.z()}}};
    if (!o.look.texture.empty()) {
      object["look"]["texture"] = o.look.texture.string();
    }
    if (o.look.shading != Shading::kSmooth) {
      object["look"]["shading"] = shading_name(o.look.shading);
      object["look"]["sharp_angle"] = o.look.sharp_angle;
    }
    if (o.source_vertex_count > 0) {
      object["source_vertex_count"] = o.source_vertex_count;
      if (!o.source_vertices.empty()) {
        object["source_vertices"] = o.source_vertices;
      }
    }
    objects.push_back(std::move(object));
  }
  Json bounds = Json::array();
  for (const FrameBounds& b : m.frame_bounds) {
    bounds.push_back(bounds_json(b));
  }
  Json json = {
      {"format", CacheManifest::kFormat},
      {"format_version", CacheManifest::kFormatVersion},
      {"dinam_version", m.dinam_version},
      {"created", m.created},
      {"scene", {{"path", m.scene_path}, {"name", m.scene_name}, {"sha256", m.scene_sha256}}},
      {"motion_settings", settings},
      {"fps", m.fps},
      {"frame_count", m.frame_count},
      {"start_frame", 1},
      {"timestep_s", m.timestep},
      {"steps_per_frame", m.steps_per_frame},
      {"simulate_seconds", m.simulate_seconds},
      {"node_count", m.node_count},
      {"objects", objects},
      {"frame_bounds", bounds},
  };
  if (!m.usd.empty()) {
    json["usd"] = m.usd;
  }
  if (!m.tears.empty()) {
    Json tears = Json::array();
    for (const CacheTear& tear : m.tears) {
      tears.push_back({tear.frame, tear.n0, tear.n1});
    }
    json["tears"] = std::move(tears);
  }
  if (m.instants.per_frame > 0) {
    json["motion_blur"] = {{"samples", m.instants.per_frame},
                           {"shutter", m.instants.shutter},
                           {"offsets_steps", m.instants.offsets},
                           {"pc2", m.instants.pc2}};
  }
  if (!m.energy.columns.empty()) {
    Json energy = Json::object();
    for (std::size_t c = 0; c < m.energy.columns.size(); ++c) {
      Json column = Json::array();
      for (const std::vector<double>& row : m.energy.rows) {
        column.push_back(row[c]);
      }
      energy[m.energy.columns[c]] = std::move(column);
    }
    json["energy"] = std::move(energy);
  }
  write_output_file(path, json.dump(1) + '\n', "the manifest");
}

CacheManifest read_manifest(const std::filesystem::path& path) {
  RegularFileIn in(path, "the cache's manifest");
  if (!in) {
    throw UserError(FileLoc{path.string()},
                    "there is no manifest.json here, so this folder is not a complete motion "
                    "cache (an interrupted 'dinam simulate' leaves none); make one with "
                    "'dinam simulate SCENE -o FOLDER'");
  }
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parse_manifest(text, path);
}

CacheManifest parse_manifest(const std::string& text, const std::filesystem::path& path) {
  const FileLoc loc{path.string()};
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::exception& e) {  // a syntax error, or a number beyond a double's range
    throw UserError(loc, fmt::format("the manifest is not valid JSON: {}", e.what()));
  }
  try {
    if (json.at("format").get<std::string>() != CacheManifest::kFormat) {
      throw UserError(loc, "this is not the manifest of a dinam motion cache");
    }
    const int version = integer<int>(json.at("format_version"));
    if (version != CacheManifest::kFormatVersion) {
      throw UserError(loc, fmt::format("cache format version {} is not the {} this dinam reads; "
                                       "simulate again to make a new cache",
                                       version, CacheManifest::kFormatVersion));
    }
    CacheManifest m;
    m.dinam_version = json.at("dinam_version").get<std::string>();
    m.created = json.at("created").get<std::string>();
    const Json& scene = json.at("scene");
    m.scene_path = scene.at("path").get<std::string>();
    m.scene_name = scene.at("name").get<std::string>();
    m.scene_sha256 = scene.at("sha256").get<std::string>();
    for (const auto& [key, value] : json.at("motion_settings").items()) {
      m.motion_settings.push_back({key, value.get<std::string>()});
    }
    m.fps = json.at("fps").get<double>();
    m.frame_count = integer<int>(json.at("frame_count"));
    m.timestep = json.at("timestep_s").get<double>();
    m.steps_per_frame = integer<int>(json.at("steps_per_frame"));
    m.simulate_seconds = json.at("simulate_seconds").get<double>();
    m.node_count = integer<Index>(json.at("node_count"));
    for (const Json& o : json.at("objects")) {
      CacheObjectEntry entry;
      entry.name = o.at("name").get<std::string>();
      entry.first_node = integer<Index>(o.at("first_node"));
      entry.node_count = integer<Index>(o.at("node_count"));
      entry.bar_count = integer<Index>(o.at("bar_count"));
      const Json& files = o.at("files");
      entry.obj = files.at("obj").get<std::string>();
      entry.pc2 = files.value("pc2", "");
      entry.mdd = files.value("mdd", "");
      entry.source_vertex_count =
          o.contains("source_vertex_count") ? integer<Index>(o.at("source_vertex_count")) : 0;
      entry.source_vertices = o.contains("source_vertices")
                                  ? integers<Index>(o.at("source_vertices"))
                                  : std::vector<Index>{};
      if (o.contains("look")) {
        const Json& look = o.at("look");
        entry.look.surface = look.at("surface").get<bool>();
        entry.look.wires = look.at("wires").get<bool>();
        entry.look.wire_radius = look.at("wire_radius").get<float>();
        const auto color = look.at("color").get<std::array<float, 3>>();
        entry.look.color = Vec3f(color[0], color[1], color[2]);
        entry.look.texture = look.value("texture", "");
        // Smooth where the manifest says nothing (as dinam writes it, and as caches made before
        // `shading` were).
        const std::string shading = look.value("shading", "smooth");
        const std::optional<Shading> named = shading_named(shading);
        if (!named) {
          throw UserError(loc, fmt::format("object '{}' has shading '{}', not smooth, flat or "
                                           "auto; simulate again",
                                           entry.name, shading));
        }
        entry.look.shading = *named;
        entry.look.sharp_angle = look.value("sharp_angle", kDefaultSharpAngle);
        if (!std::isfinite(entry.look.sharp_angle) || entry.look.sharp_angle < 0.0 ||
            entry.look.sharp_angle > 180.0) {
          throw UserError(loc, fmt::format("object '{}' has a sharp_angle of {}, not 0 to 180 "
                                           "degrees; simulate again",
                                           entry.name, entry.look.sharp_angle));
        }
      }
      m.objects.push_back(std::move(entry));
    }
    for (const Json& b : json.at("frame_bounds")) {
      m.frame_bounds.push_back(bounds_from(b));
    }
    m.usd = json.value("usd", "");
    if (json.contains("tears")) {
      for (const Json& tear : json.at("tears")) {
        m.tears.push_back(
            {integer<int>(tear.at(0)), integer<Index>(tear.at(1)), integer<Index>(tear.at(2))});
        const CacheTear& t = m.tears.back();
        if (t.frame < 1 || t.n0 < 0 || t.n1 < 0 || t.n0 >= m.node_count || t.n1 >= m.node_count) {
          throw UserError(loc, "the manifest names a tear outside the frames or the nodes");
        }
      }
    }
    if (json.contains("motion_blur")) {
      const Json& blur = json.at("motion_blur");
      m.instants.per_frame = integer<int>(blur.at("samples"));
      m.instants.shutter = blur.at("shutter").get<double>();
      m.instants.offsets = integers<int>(blur.at("offsets_steps"));
      m.instants.pc2 = blur.at("pc2").get<std::string>();
      if (m.instants.per_frame < 1 ||
          m.instants.offsets.size() != static_cast<std::size_t>(m.instants.per_frame)) {
        throw UserError(loc, "the manifest's motion_blur is inconsistent (samples, offsets)");
      }
    }
    if (json.contains("energy")) {
      for (const auto& [name, column] : json.at("energy").items()) {
        m.energy.columns.push_back(name);
        m.energy.rows.resize(std::max(m.energy.rows.size(), column.size()));
        for (std::size_t k = 0; k < column.size(); ++k) {
          m.energy.rows[k].push_back(column[k].get<double>());
        }
      }
    }
    if (m.frame_count < 1) {
      throw UserError(loc, fmt::format("the cache holds {} frames: there is nothing to draw or "
                                       "play; simulate a scene of at least one frame",
                                       m.frame_count));
    }
    if (m.frame_bounds.size() != static_cast<std::size_t>(m.frame_count) || m.fps <= 0.0 ||
        m.objects.empty()) {
      throw UserError(loc, "the manifest is inconsistent (frame bounds, fps or objects)");
    }
    // The files it names are the cache's own: a name with a folder in it (../../etc/passwd)
    // would have a reader open a file outside the cache.
    Index next_node = 0;
    for (const CacheObjectEntry& entry : m.objects) {
      require_file_name(loc, entry.obj, entry.name, "obj", false);
      require_file_name(loc, entry.pc2, entry.name, "pc2", true);
      require_file_name(loc, entry.mdd, entry.name, "mdd", true);
      require_file_name(loc, entry.look.texture.string(), entry.name, "texture", true);
      if (entry.pc2.empty() && entry.mdd.empty() && m.usd.empty()) {
        throw UserError(loc, fmt::format("object '{}' names no point cache (pc2 or mdd), and the "
                                         "cache no USD stage",
                                         entry.name));
      }
      if (entry.first_node != next_node || entry.node_count < 1 ||
          entry.first_node + entry.node_count > m.node_count) {
        throw UserError(loc, fmt::format("object '{}' holds points {} to {} of the cache's {}, "
                                         "which do not follow the objects before it",
                                         entry.name, entry.first_node,
                                         entry.first_node + entry.node_count - 1, m.node_count));
      }
      next_node += entry.node_count;
    }
    require_file_name(loc, m.usd, "the stage", "usd", true);
    require_file_name(loc, m.instants.pc2, "the motion blur", "pc2", true);
    return m;
  } catch (const Json::exception& e) {
    throw UserError(
        loc, fmt::format("the manifest lacks a value or has one of the wrong type: {}", e.what()));
  } catch (const std::invalid_argument& e) {
    throw UserError(loc, fmt::format("the manifest has a count that is not one: {}", e.what()));
  }
}

}  // namespace dinam
