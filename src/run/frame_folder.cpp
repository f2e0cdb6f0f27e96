#include "run/frame_folder.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/wall_clock.hpp"
#include "run/movie_format.hpp"

namespace dinam {
namespace {

using Json = nlohmann::ordered_json;

}  // namespace

int frame_number_digits(int frame_count) {
  return std::max(4, static_cast<int>(std::to_string(frame_count).size()));
}

std::string frame_file_name(int frame, int frame_count) {
  return fmt::format("frame_{:0{}}.png", frame, frame_number_digits(frame_count));
}

void write_frame_folder_info(const std::filesystem::path& folder, const FrameFolderInfo& info) {
  const Json json = {
      {"name", info.name},   {"fps", info.fps},       {"frame_count", info.frame_count},
      {"width", info.width}, {"height", info.height}, {"movie", movie_format_name(info.movie)}};
  write_output_file(folder / kFrameFolderInfoName, json.dump(1) + '\n', "the frame folder's info");
}

FrameFolderInfo read_frame_folder_info(const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / kFrameFolderInfoName;
  const FileLoc loc{path.string()};
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw UserError(loc, fmt::format("no {} here: {} holds no frames drawn by 'dinam render' "
                                     "(it writes this file beside them)",
                                     kFrameFolderInfoName, folder.string()));
  }
  try {
    const Json json = Json::parse(in);
    FrameFolderInfo info;
    info.name = json.at("name").get<std::string>();
    info.fps = json.at("fps").get<double>();
    info.frame_count = json.at("frame_count").get<int>();
    info.width = json.at("width").get<int>();
    info.height = json.at("height").get<int>();
    info.movie = parse_movie_format(json.at("movie").get<std::string>());
    if (info.name.empty() || info.name.find('/') != std::string::npos || !(info.fps > 0.0) ||
        info.frame_count < 1 || info.width < 1 || info.height < 1) {
      throw UserError(loc, "the frame folder's description has an impossible value");
    }
    return info;
  } catch (const Json::exception& e) {
    throw UserError(loc, fmt::format("not a frame folder description: {}", e.what()));
  }
}

FrameInventory take_inventory(const std::filesystem::path& folder, const FrameFolderInfo& info) {
  const int digits = frame_number_digits(info.frame_count);
  std::vector<bool> present(static_cast<std::size_t>(info.frame_count) + 1, false);
  FrameInventory inventory;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("frame_", 0) != 0 || entry.path().extension() != ".png") {
      continue;
    }
    const std::string_view number(name.data() + 6, name.size() - 6 - 4);
    int frame = 0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), frame);
    const bool ours = error == std::errc() && end == number.data() + number.size() &&
                      static_cast<int>(number.size()) == digits && frame >= 1 &&
                      frame <= info.frame_count;
    if (ours) {
      present[static_cast<std::size_t>(frame)] = true;
    } else {
      inventory.extra.push_back(name);
    }
  }
  for (int frame = 1; frame <= info.frame_count; ++frame) {
    if (!present[static_cast<std::size_t>(frame)]) {
      inventory.missing.push_back(frame);
    }
  }
  std::sort(inventory.extra.begin(), inventory.extra.end());
  return inventory;
}

std::string number_ranges(const std::vector<int>& numbers) {
  std::string text;
  for (std::size_t i = 0; i < numbers.size();) {
    std::size_t j = i;
    while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1) {
      ++j;
    }
    text += text.empty() ? "" : ", ";
    text += j == i ? fmt::format("{}", numbers[i]) : fmt::format("{}-{}", numbers[i], numbers[j]);
    i = j + 1;
  }
  return text;
}

}  // namespace dinam
