#pragma once
// What the tests of bad input and of hostile output names share: a small scene, and checks on
// what a run printed and left in a folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace dinam::test {

inline std::string read_text(const std::filesystem::path& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

// Every regular file under `folder`, as paths relative to it.
inline std::vector<std::string> files_under(const std::filesystem::path& folder) {
  std::vector<std::string> files;
  std::error_code ec;
  if (!std::filesystem::exists(folder, ec)) {
    return files;
  }
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!entry.is_directory()) {
      files.push_back(entry.path().lexically_relative(folder).string());  // links not followed
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

inline std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) {
    text += (text.empty() ? "" : ", ") + name;
  }
  return text;
}

inline void expect_message(const CommandResult& run, const std::vector<std::string>& fragments) {
  for (const std::string& fragment : fragments) {
    EXPECT_NE(run.output.find(fragment), std::string::npos)
        << "the message lacks '" << fragment << "':\n"
        << run.output;
  }
}

// A small scene that renders in a fraction of a second: 20 frames of a five-node rope.
inline std::string rope_scene() {
  return "version: 1\n"
         "name: rope\n"
         "duration: 1.0\n"
         "fps: 20\n"
         "gravity: [0, 0, -9.81]\n"
         "image: {width: 64, height: 36}\n"
         "objects:\n"
         "  - name: rope\n"
         "    mesh:\n"
         "      polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 4}\n"
         "    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.01}\n"
         "    pinned: {indices: [0]}\n";
}

}  // namespace dinam::test
