#pragma once
// The energy accounts as a picture: energy.svg beside energy.csv, each account against time, so
// that whether a run kept its balance shows without plotting the CSV oneself.
#include <array>
#include <vector>

#include "core/output_file.hpp"
#include "run/energy_csv.hpp"

namespace dinam {

// Writes the plot of `rows` (energy_row's, one per frame) to `file` and commits it (renamed into
// place when whole: core/output_file.hpp). Accounts that stay zero are left out; the title gives
// the balance's worst deviation from its first value, as a share of the peak kinetic energy.
void write_energy_plot(OutputFile& file,
                       const std::vector<std::array<double, kEnergyColumns.size()>>& rows);

}  // namespace dinam
