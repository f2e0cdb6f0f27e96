#include "scene/yaml_map.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <exception>
#include <map>
#include <optional>
#include <regex>
#include <string>

namespace dinam {
namespace {

// The first tab in a line's indentation, as a file location (line and column, 1-based); none
// where every line is indented with spaces.
std::optional<std::pair<int, int>> first_indenting_tab(const std::string& text) {
  int line = 1;
  bool indenting = true;
  int column = 1;
  for (const char c : text) {
    if (c == '\n') {
      ++line;
      column = 1;
      indenting = true;
      continue;
    }
    if (indenting && c == '\t') {
      return std::pair{line, column};
    }
    indenting = indenting && c == ' ';
    ++column;
  }
  return std::nullopt;
}

std::string describe(const YAML::Node& node) {
  if (node.IsScalar()) {
    return fmt::format("'{}'", node.Scalar());
  }
  if (node.IsSequence()) {
    return "a list";
  }
  if (node.IsMap()) {
    return "a map";
  }
  return "nothing";
}

// Levenshtein distance, for "did you mean" suggestions.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string lowered(std::string text) {
  for (char& c : text) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return text;
}

}  // namespace

std::string did_you_mean(const std::string& given, const std::vector<std::string>& candidates) {
  std::string hint;
  std::size_t best = 3;  // within two edits
  for (const std::string& candidate : candidates) {
    const std::size_t d = edit_distance(lowered(given), lowered(candidate));
    if (d < best) {
      best = d;
      hint = fmt::format(" (did you mean '{}'?)", candidate);
    }
  }
  return hint;
}

FileLoc loc_of(const YAML::Node& node, const std::string& file) {
  const YAML::Mark mark = node.IsDefined() ? node.Mark() : YAML::Mark::null_mark();
  if (mark.is_null()) {
    return FileLoc{file, 0, 0};
  }
  return FileLoc{file, mark.line + 1, mark.column + 1};
}

// A number written with a unit ("200 GPa", "5 mm", "3 kg"), in SI base units (grams as kg), or
// empty where the text is not one.
std::optional<double> in_si_units(const std::string& text) {
  static const std::regex number_and_unit(
      R"(\s*([-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)\s*([a-zA-Z]+)\s*)");
  // std::regex recurses per character: only text as short as a number and its unit is tried.
  constexpr std::size_t kLongest = 40;
  std::smatch match;
  if (text.size() > kLongest || !std::regex_match(text, match, number_and_unit)) {
    return std::nullopt;
  }
  static const std::map<std::string, double> units = {
      {"Pa", 1.0}, {"N", 1.0}, {"m", 1.0}, {"s", 1.0}, {"Hz", 1.0}, {"J", 1.0}, {"g", 1e-3}};
  static const std::map<char, double> prefixes = {{'G', 1e9},  {'M', 1e6},  {'k', 1e3}, {'c', 1e-2},
                                                  {'m', 1e-3}, {'u', 1e-6}, {'n', 1e-9}};
  const std::string unit = match[2].str();
  double scale = 0.0;
  if (const auto base = units.find(unit); base != units.end()) {
    scale = base->second;
  } else if (const auto prefix = prefixes.find(unit.front());
             prefix != prefixes.end() && units.contains(unit.substr(1))) {
    scale = prefix->second * units.at(unit.substr(1));
  } else {
    return std::nullopt;
  }
  // strtod, not stod: a number past double's range ("6666666666666E66666 m", found by fuzzing)
  // is no number here, rather than an exception nothing catches.
  const double value = std::strtod(match[1].str().c_str(), nullptr) * scale;
  return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

double as_double(const YAML::Node& node, const std::string& file, const std::string& what) {
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value)) {
    if (node.IsScalar()) {
      if (const std::optional<double> si = in_si_units(node.Scalar())) {
        throw_user_error(loc_of(node, file),
                         "'{}' must be a number, got {}: units are not read; give it in SI base "
                         "units (Pa, N, m, s, kg) as a plain number, here {:g}",
                         what, describe(node), *si);
      }
    }
    throw_user_error(loc_of(node, file), "'{}' must be a number, got {}", what, describe(node));
  }
  if (!std::isfinite(value)) {
    throw_user_error(loc_of(node, file), "'{}' must be a finite number, got {}", what,
                     describe(node));
  }
  return value;
}

int as_int(const YAML::Node& node, const std::string& file, const std::string& what) {
  int value = 0;
  if (!node.IsScalar() || !YAML::convert<int>::decode(node, value)) {
    throw_user_error(loc_of(node, file), "'{}' must be a whole number, got {}", what,
                     describe(node));
  }
  return value;
}

bool as_bool(const YAML::Node& node, const std::string& file, const std::string& what) {
  bool value = false;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value)) {
    throw_user_error(loc_of(node, file), "'{}' must be true or false, got {}", what,
                     describe(node));
  }
  return value;
}

std::string as_string(const YAML::Node& node, const std::string& file, const std::string& what) {
  if (!node.IsScalar()) {
    throw_user_error(loc_of(node, file), "'{}' must be a text value, got {}", what, describe(node));
  }
  return node.Scalar();
}

Vec3 as_vec3(const YAML::Node& node, const std::string& file, const std::string& what) {
  if (!node.IsSequence() || node.size() != 3) {
    throw_user_error(loc_of(node, file), "'{}' must be a list of three numbers [x, y, z], got {}",
                     what, describe(node));
  }
  return {as_double(node[0], file, what + "[0]"), as_double(node[1], file, what + "[1]"),
          as_double(node[2], file, what + "[2]")};
}

void require_utf8(const std::string& text, const FileLoc& loc, const std::string& what) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto lead = static_cast<unsigned char>(text[i]);
    // The length of the sequence and the least its value may be (shorter forms are not UTF-8).
    const std::size_t length = lead < 0x80           ? 1
                               : (lead >> 5) == 0x6  ? 2
                               : (lead >> 4) == 0xE  ? 3
                               : (lead >> 3) == 0x1E ? 4
                                                     : 0;
    bool valid = length > 0 && i + length <= text.size();
    std::uint32_t code = length == 1 ? lead : lead & (0x7Fu >> length);
    for (std::size_t k = 1; valid && k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      valid = (next >> 6) == 0x2;
      code = (code << 6) | (next & 0x3Fu);
    }
    constexpr std::uint32_t kLeast[] = {0, 0, 0x80, 0x800, 0x10000};
    valid = valid && code >= kLeast[length] && code <= 0x10FFFF && (code < 0xD800 || code > 0xDFFF);
    if (!valid) {
      throw_user_error(loc,
                       "'{}' is not UTF-8 text (byte {} of it is not): write the name in UTF-8, "
                       "as every editor saves it by default",
                       what, i + 1);
    }
    i += length;
  }
}

void require_plain_name(const std::string& text, const FileLoc& loc, const std::string& what) {
  require_utf8(text, loc, what);
  if (text.empty() || text == "." || text == "..") {
    throw_user_error(loc,
                     "'{}' is '{}', which names a folder, not a thing: it goes into file names; "
                     "give it a name",
                     what, text);
  }
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    // C1 controls are U+0080–U+009F, in UTF-8 0xC2 followed by 0x80–0x9F.
    const bool c1 = c == 0xC2 && i + 1 < text.size() &&
                    static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(text[i + 1]) <= 0x9F;
    if (c < 0x20 || c == 0x7F || c1) {
      const unsigned code = c1 ? static_cast<unsigned char>(text[i + 1]) : c;
      throw_user_error(loc,
                       "'{}' holds a control character (U+{:04X}, at byte {}), which would break "
                       "the files and reports it goes into; write the name in printable characters",
                       what, code, i + 1);
    }
  }
}

void check_no_duplicate_keys(const YAML::Node& root, const std::string& file) {
  // Aliases can make a small file a huge tree (the "billion laughs"); a scene has far fewer
  // nodes than this, so a document beyond it is refused rather than walked.
  constexpr std::size_t kMaxNodes = 10'000'000;
  std::size_t visited = 0;
  std::vector<YAML::Node> pending = {root};
  while (!pending.empty()) {
    const YAML::Node node = pending.back();
    pending.pop_back();
    if (++visited > kMaxNodes) {
      throw_user_error(loc_of(root, file),
                       "the scene expands to more than {} YAML nodes (through "
                       "aliases?); that is no scene dinam can read",
                       kMaxNodes);
    }
    if (node.IsMap()) {
      std::map<std::string, YAML::Node> keys;
      for (const auto& entry : node) {
        if (entry.first.IsScalar()) {
          const auto [earlier, first_time] = keys.emplace(entry.first.Scalar(), entry.first);
          if (!first_time) {
            throw_user_error(loc_of(entry.first, file),
                             "the key '{}' appears twice in one map (first at {}); YAML allows a "
                             "key once: keep one of them",
                             entry.first.Scalar(), loc_of(earlier->second, file).to_string());
          }
        }
        pending.push_back(entry.second);
      }
    } else if (node.IsSequence()) {
      for (const auto& item : node) {
        pending.push_back(item);
      }
    }
  }
}

YamlMap::YamlMap(const YAML::Node& node, std::string file, std::string path)
    : node_(node), file_(std::move(file)), path_(std::move(path)), not_a_map_(!node_.IsMap()) {}

// Throwing here is deliberate and safe: only when no other exception is in flight, and the error
// is the scene's, which every caller reports.
// NOLINTNEXTLINE(bugprone-exception-escape)
YamlMap::~YamlMap() noexcept(false) {
  // A reader that stopped before finish() on a node that is no map: the error is still due,
  // unless another error is already on its way.
  if (not_a_map_ && !reported_ && std::uncaught_exceptions() == 0) {
    throw_not_a_map();
  }
}

void YamlMap::throw_not_a_map(const std::string& wanted) const {
  reported_ = true;
  std::string keys;
  for (const std::string& key : asked_in_order_) {
    keys += (keys.empty() ? "" : ", ") + key;
  }
  std::string fix;
  if (!wanted.empty() && node_.IsScalar()) {
    fix = fmt::format(": write {{{}: {}}}", wanted, node_.Scalar());
  }
  throw_user_error(loc_of(node_, file_), "'{}' must be a map of keys{}, got {}{}", name(),
                   keys.empty() ? "" : " (" + keys + ")", describe(node_), fix);
}

std::string YamlMap::path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

bool YamlMap::has(const std::string& key) {
  return static_cast<bool>(get(key));
}

YAML::Node YamlMap::get(const std::string& key) {
  if (asked_.insert(key).second) {
    asked_in_order_.push_back(key);
  }
  if (not_a_map_) {
    return YAML::Node(YAML::NodeType::Undefined);  // indexing a scalar would make it a map
  }
  // Looked up through a const node: yaml-cpp's non-const operator[] adds a pair for a key it lacks,
  // which would invalidate an iteration over the same map (a tolerance file whose scene key is
  // null, found by fuzzing, read freed memory).
  const YAML::Node& map = node_;
  return map[key];
}

YAML::Node YamlMap::required(const std::string& key) {
  const YAML::Node value = get(key);
  if (value) {
    return value;
  }
  if (not_a_map_) {
    throw_not_a_map(key);
  }
  for (const auto& entry : node_) {
    const std::string present = entry.first.Scalar();
    if (!asked_.contains(present) && edit_distance(present, key) <= 2) {
      throw_user_error(loc_of(entry.first, file_),
                       "unknown key '{}' in '{}' (did you mean '{}'?); '{}' is required", present,
                       name(), key, key);
    }
  }
  throw_user_error(loc(), "'{}' is missing the required key '{}'", name(), key);
}

double YamlMap::number(const std::string& key, double fallback) {
  const YAML::Node value = get(key);
  return value ? as_double(value, file_, path(key)) : fallback;
}

double YamlMap::required_number(const std::string& key) {
  return as_double(required(key), file_, path(key));
}

int YamlMap::integer(const std::string& key, int fallback) {
  const YAML::Node value = get(key);
  return value ? as_int(value, file_, path(key)) : fallback;
}

bool YamlMap::boolean(const std::string& key, bool fallback) {
  const YAML::Node value = get(key);
  return value ? as_bool(value, file_, path(key)) : fallback;
}

std::string YamlMap::string(const std::string& key, const std::string& fallback) {
  const YAML::Node value = get(key);
  return value ? as_string(value, file_, path(key)) : fallback;
}

Vec3 YamlMap::vec3(const std::string& key, const Vec3& fallback) {
  const YAML::Node value = get(key);
  return value ? as_vec3(value, file_, path(key)) : fallback;
}

Vec3 YamlMap::required_vec3(const std::string& key) {
  return as_vec3(required(key), file_, path(key));
}

FileLoc YamlMap::loc(const std::string& key) const {
  if (not_a_map_) {
    return loc();
  }
  const YAML::Node value = node_[key];
  return value ? loc_of(value, file_) : loc();
}

void YamlMap::finish() const {
  if (not_a_map_) {
    throw_not_a_map();
  }
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();
    if (asked_.contains(key)) {
      continue;
    }
    const std::string hint =
        did_you_mean(key, std::vector<std::string>(asked_.begin(), asked_.end()));
    std::string known_list;
    for (const std::string& known : asked_) {
      known_list += (known_list.empty() ? "" : ", ") + known;
    }
    throw_user_error(loc_of(entry.first, file_), "unknown key '{}' in '{}'{}; known keys: {}", key,
                     name(), hint, known_list);
  }
}

YAML::Node parse_yaml(const std::string& text, const std::filesystem::path& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    // YAML indents with spaces only; a tab there reads as a broken structure ("end of map not
    // found"), so the tab itself is named.
    if (const auto tab = first_indenting_tab(text)) {
      throw UserError(FileLoc{source.string(), tab->first, tab->second},
                      "a tab indents this line, and YAML indents with spaces only: replace it "
                      "with spaces (the YAML parser says: " +
                          e.msg + ")");
    }
    throw UserError(FileLoc{source.string(), e.mark.line + 1, e.mark.column + 1},
                    "this is not valid YAML: " + e.msg);
  }
  return root;
}

}  // namespace dinam
