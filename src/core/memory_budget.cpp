#include "core/memory_budget.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "core/error.hpp"

namespace dinam {
namespace {

std::optional<std::uint64_t> read_number_file(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::string text;
  if (!(file >> text) || text.empty() || !std::isdigit(static_cast<unsigned char>(text[0]))) {
    return std::nullopt;  // missing, or "max"
  }
  return std::strtoull(text.c_str(), nullptr, 10);
}

std::optional<std::uint64_t> mem_available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kilobytes = 0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit) {
    if (key == "MemAvailable:") {
      return kilobytes * 1024;
    }
  }
  return std::nullopt;
}

// The cgroup (v2) this process runs in: "0::/path" in /proc/self/cgroup.
std::optional<std::filesystem::path> cgroup_folder() {
  std::ifstream cgroup("/proc/self/cgroup");
  std::string line;
  while (std::getline(cgroup, line)) {
    if (line.rfind("0::", 0) == 0) {
      return std::filesystem::path("/sys/fs/cgroup") / line.substr(3).erase(0, 1);
    }
  }
  return std::nullopt;
}

std::uint64_t parse_memory_limit(const std::string& text) {
  std::size_t used = 0;
  double value = -1.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  std::string suffix = text.substr(used);
  if (!suffix.empty() && (suffix.back() == 'B' || suffix.back() == 'b')) {
    suffix.pop_back();
  }
  double scale = 0.0;
  if (suffix.empty()) {
    scale = 1.0;
  } else if (suffix.size() == 1) {
    const std::string units = "KMGT";
    const std::size_t power = units.find(static_cast<char>(std::toupper(suffix[0])));
    scale = power == std::string::npos ? 0.0 : std::pow(1024.0, static_cast<double>(power + 1));
  }
  if (used == 0 || scale == 0.0 || !std::isfinite(value) || value < 0.0 || value * scale > 1e19) {
    throw_user_error({},
                     "DINAM_MEMORY_LIMIT is '{}'; give bytes or a number with K, M, G or T, e.g. "
                     "DINAM_MEMORY_LIMIT=8G, or 0 for no limit of its own",
                     text);
  }
  return static_cast<std::uint64_t>(value * scale);
}

}  // namespace

MemoryBudget available_memory() {
  std::optional<MemoryBudget> budget;
  const auto consider = [&](std::uint64_t bytes, std::string source) {
    if (!budget || bytes < budget->bytes) {
      budget = MemoryBudget{bytes, std::move(source)};
    }
  };
  if (const std::optional<std::uint64_t> available = mem_available()) {
    consider(*available, "MemAvailable in /proc/meminfo");
  }
  if (const std::optional<std::filesystem::path> folder = cgroup_folder()) {
    const std::optional<std::uint64_t> limit = read_number_file(*folder / "memory.max");
    const std::optional<std::uint64_t> current = read_number_file(*folder / "memory.current");
    if (limit && current) {
      consider(*limit > *current ? *limit - *current : 0,
               fmt::format("the limit of cgroup {} less what it uses", folder->string()));
    }
  }
  if (const char* text = std::getenv("DINAM_MEMORY_LIMIT"); text != nullptr && *text != '\0') {
    if (const std::uint64_t limit = parse_memory_limit(text); limit > 0) {
      consider(limit, "DINAM_MEMORY_LIMIT");
    }
  }
  return budget.value_or(MemoryBudget{});
}

}  // namespace dinam
