#pragma once
// A small text file read whole: the kernel's files under /proc and /sys/fs/cgroup, which the thread
// count reads (core/cpu_share.hpp, core/machine_load.hpp). None when it cannot be opened.
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace dinam {

inline std::optional<std::string> read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace dinam
