#pragma once
// Typed access to YAML with source locations. YamlMap remembers which keys were read; finish()
// turns every key nobody read into an error, so a typo such as `densty:` is caught at its line
// instead of silently falling back to a default (pbrt's ReportUnused).
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace dinam {

FileLoc loc_of(const YAML::Node& node, const std::string& file);

// " (did you mean 'x'?)" for the candidate nearest `given` (within two edits, letters compared
// whatever their case), or "" where none is that near.
std::string did_you_mean(const std::string& given, const std::vector<std::string>& candidates);

// The YAML document in `text`, read from `source`; throws UserError at the line and column of a
// syntax error, naming a tab that indents a line where there is one.
YAML::Node parse_yaml(const std::string& text, const std::filesystem::path& source);

// Conversions that name the location and the key on failure. `what` is the key path, e.g.
// "objects[0].material.density".
double as_double(const YAML::Node& node, const std::string& file, const std::string& what);
int as_int(const YAML::Node& node, const std::string& file, const std::string& what);
bool as_bool(const YAML::Node& node, const std::string& file, const std::string& what);
std::string as_string(const YAML::Node& node, const std::string& file, const std::string& what);
Vec3 as_vec3(const YAML::Node& node, const std::string& file, const std::string& what);

// Throws UserError at `loc` unless `text` is UTF-8: names go into JSON manifests, USD stages and
// web pages, which hold nothing else.
void require_utf8(const std::string& text, const FileLoc& loc, const std::string& what);

// A name that goes into file names and into every format dinam writes (the scene's, an
// object's): UTF-8, not empty, not a path word ('.', '..'), and without control characters (C0,
// DEL, C1), which would break a JUnit report's XML, reach a terminal as escape sequences, or end a
// USD string. Throws UserError at `loc` naming `what` and the first offending character.
void require_plain_name(const std::string& text, const FileLoc& loc, const std::string& what);

// Throws UserError at the second occurrence of a key within one map, anywhere in the document,
// naming the first: YAML forbids it, yet the parser keeps both and a reader would silently use one.
void check_no_duplicate_keys(const YAML::Node& root, const std::string& file);

class YamlMap {
 public:
  // A node that is not a map (`turbulence: 0.5`) reads as one without keys until the reader has
  // asked for the keys it knows: then finish(), or required(), or at the latest the destructor,
  // throws UserError naming them, so the message can say what the map holds.
  YamlMap(const YAML::Node& node, std::string file, std::string path);
  YamlMap(const YamlMap&) = delete;
  YamlMap& operator=(const YamlMap&) = delete;
  ~YamlMap() noexcept(false);  // NOLINT(bugprone-exception-escape): see yaml_map.cpp

  // Whether `key` is present; asking counts it among the keys the map accepts (finish()).
  bool has(const std::string& key);
  // Marks `key` as read and returns it (an undefined node when absent).
  YAML::Node get(const std::string& key);
  // The same, but a missing key is an error. When a present key is a near miss (`densty` for
  // `density`), the error is about that typo, at its line.
  YAML::Node required(const std::string& key);

  double number(const std::string& key, double fallback);
  double required_number(const std::string& key);
  int integer(const std::string& key, int fallback);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  Vec3 vec3(const std::string& key, const Vec3& fallback);
  Vec3 required_vec3(const std::string& key);

  // Location of the value under `key` (of the map itself when absent).
  FileLoc loc(const std::string& key) const;
  FileLoc loc() const { return loc_of(node_, file_); }
  std::string path(const std::string& key) const;
  // The map's own key path, for messages ("objects[0].material"; "the scene" at the root).
  std::string name() const { return path_.empty() ? "the scene" : path_; }
  const std::string& file() const { return file_; }

  // Throws on the first key that was never read, suggesting the nearest key that was asked for.
  // Call it after every key this map may hold has been asked for.
  void finish() const;

 private:
  // Throws the error of a node that is not a map, listing the keys asked for; `wanted`, a
  // required key, is suggested as the one its value belongs to.
  [[noreturn]] void throw_not_a_map(const std::string& wanted = "") const;

  YAML::Node node_;
  std::string file_;
  std::string path_;
  std::set<std::string> asked_;  // every key asked for, present or not
  std::vector<std::string> asked_in_order_;
  bool not_a_map_ = false;
  mutable bool reported_ = false;  // its error was thrown
};

}  // namespace dinam
