#pragma once
// The energy accounts as CSV, one row per frame, written beside the frames under a new temporary
// name and renamed when the run completes (core/output_file.hpp); with energy.svg beside it, their
// plot (energy_plot.hpp).
#include <array>
#include <filesystem>
#include <vector>

#include "core/output_file.hpp"
#include "dynamics/state.hpp"

namespace dinam {

// The report's columns, each a name with its unit, and one frame's values in that order.
inline constexpr std::array<const char*, 16> kEnergyColumns = {"time_s",
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
                                                               "support_work_J",
                                                               "numerical_dissipation_J",
                                                               "total_J"};
std::array<double, kEnergyColumns.size()> energy_row(const EnergyReport& report);

class EnergyCsv {
 public:
  // Writes the header, and opens the plot's file (`path` with .svg) beside it; throws
  // RuntimeError, or UserError for a final name that is a link, before the run. An unclosed file
  // is removed when the EnergyCsv goes.
  explicit EnergyCsv(const std::filesystem::path& path);

  void write(const EnergyReport& report);
  void close();  // flushes and renames to the final name, and writes the plot beside it

 private:
  OutputFile file_;
  OutputFile plot_;
  std::vector<std::array<double, kEnergyColumns.size()>> rows_;  // for the plot
};

}  // namespace dinam
