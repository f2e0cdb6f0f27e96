#pragma once
// The energy accounts as CSV, one row per frame, written beside the frames under a temporary
// name and renamed when the run completes.
#include <array>
#include <cstdio>
#include <filesystem>

#include "dynamics/state.hpp"

namespace dinam {

// The report's columns, each a name with its unit, and one frame's values in that order.
inline constexpr std::array<const char*, 14> kEnergyColumns = {"time_s",
                                                               "kinetic_J",
                                                               "axial_J",
                                                               "bending_J",
                                                               "torsion_J",
                                                               "gravitational_J",
                                                               "contact_J",
                                                               "damping_work_J",
                                                               "plastic_dissipation_J",
                                                               "friction_work_J",
                                                               "contact_damping_work_J",
                                                               "wind_work_J",
                                                               "field_work_J",
                                                               "total_J"};
std::array<double, kEnergyColumns.size()> energy_row(const EnergyReport& report);

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
