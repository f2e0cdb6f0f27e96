#pragma once
// The energy accounts as CSV, one row per frame, written beside the frames under a temporary
// name and renamed when the run completes.
#include <cstdio>
#include <filesystem>

#include "dynamics/state.hpp"

namespace dinam {

class EnergyCsv {
 public:
  explicit EnergyCsv(std::filesystem::path path);  // writes the header; throws RuntimeError
  ~EnergyCsv();                                    // an unclosed file is removed
  EnergyCsv(const EnergyCsv&) = delete;
  EnergyCsv& operator=(const EnergyCsv&) = delete;

  void write(const EnergyReport& report);
  void close();  // flushes and renames to the final name

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::FILE* file_ = nullptr;
};

}  // namespace dinam
