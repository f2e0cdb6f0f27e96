#include "run/energy_csv.hpp"

#include "run/energy_plot.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dinam {

std::array<double, kEnergyColumns.size()> energy_row(const EnergyReport& r) {
  const EnergyAccounts& a = r.accounts;
  return {r.time,
          r.kinetic,
          r.axial,
          r.bending,
          r.torsion,
          r.gravitational,
          r.contact,
          a.damping_work,
          a.plastic_dissipation,
          a.friction_work,
          a.contact_damping_work,
          a.wind_work,
          a.field_work,
          a.support_work,
          a.numerical_dissipation,
          r.total};
}

EnergyCsv::EnergyCsv(const std::filesystem::path& path)
    : file_(path), plot_(std::filesystem::path(path).replace_extension(".svg")) {
  fmt::print(file_.stream(), "{}\n", fmt::join(kEnergyColumns, ","));
}

void EnergyCsv::write(const EnergyReport& report) {
  const auto row = energy_row(report);
  rows_.push_back(row);
  fmt::print(file_.stream(), "{:.6f}", row[0]);  // the time; the energies to 9 significant digits
  for (std::size_t c = 1; c < row.size(); ++c) {
    fmt::print(file_.stream(), ",{:.9g}", row[c]);
  }
  std::fputc('\n', file_.stream());
}

void EnergyCsv::close() {
  file_.commit();
  write_energy_plot(plot_, rows_);
}

}  // namespace dinam
