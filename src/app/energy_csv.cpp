#include "app/energy_csv.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "core/error.hpp"

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
          r.total};
}

EnergyCsv::EnergyCsv(std::filesystem::path path) : path_(std::move(path)) {
  temporary_ = path_;
  temporary_ += ".tmp";
  file_ = std::fopen(temporary_.c_str(), "w");
  if (file_ == nullptr) {
    throw RuntimeError(
        fmt::format("cannot write {}: {}", temporary_.string(), std::strerror(errno)));
  }
  fmt::print(file_, "{}\n", fmt::join(kEnergyColumns, ","));
}

EnergyCsv::~EnergyCsv() {
  if (file_ != nullptr) {
    std::fclose(file_);
    std::error_code ec;
    std::filesystem::remove(temporary_, ec);
  }
}

void EnergyCsv::write(const EnergyReport& report) {
  const auto row = energy_row(report);
  fmt::print(file_, "{:.6f}", row[0]);  // the time; the energies to 9 significant digits
  for (std::size_t c = 1; c < row.size(); ++c) {
    fmt::print(file_, ",{:.9g}", row[c]);
  }
  std::fputc('\n', file_);
}

void EnergyCsv::close() {
  const bool ok = std::fclose(file_) == 0;
  file_ = nullptr;
  std::error_code ec;
  if (ok) {
    std::filesystem::rename(temporary_, path_, ec);
  }
  if (!ok || ec) {
    std::filesystem::remove(temporary_, ec);
    throw RuntimeError(fmt::format("cannot write {}", path_.string()));
  }
}

}  // namespace dinam
