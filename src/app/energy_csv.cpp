#include "app/energy_csv.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "core/error.hpp"

namespace dinam {

EnergyCsv::EnergyCsv(std::filesystem::path path) : path_(std::move(path)) {
  temporary_ = path_;
  temporary_ += ".tmp";
  file_ = std::fopen(temporary_.c_str(), "w");
  if (file_ == nullptr) {
    throw RuntimeError(
        fmt::format("cannot write {}: {}", temporary_.string(), std::strerror(errno)));
  }
  fmt::print(file_,
             "time_s,kinetic_J,axial_J,bending_J,torsion_J,gravitational_J,contact_J,"
             "damping_work_J,plastic_dissipation_J,friction_work_J,contact_damping_work_J,"
             "wind_work_J,field_work_J,total_J\n");
}

EnergyCsv::~EnergyCsv() {
  if (file_ != nullptr) {
    std::fclose(file_);
    std::error_code ec;
    std::filesystem::remove(temporary_, ec);
  }
}

void EnergyCsv::write(const EnergyReport& r) {
  const EnergyAccounts& a = r.accounts;
  fmt::print(file_,
             "{:.6f},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{"
             ":.9g},{:.9g}\n",
             r.time, r.kinetic, r.axial, r.bending, r.torsion, r.gravitational, r.contact,
             a.damping_work, a.plastic_dissipation, a.friction_work, a.contact_damping_work,
             a.wind_work, a.field_work, r.total);
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
