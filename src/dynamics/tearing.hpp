#pragma once
// Tearing (beyond the paper): a bar whose strain or tension reaches its material's breaking value
// breaks for good at that step, and every spring that stands on it (model/tearing.cpp) and every
// face it is an edge of go with it. The check runs serially over the bars in id order at the
// start of each step, so what breaks, and when, does not depend on the thread count.
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// The broken flags, all 0, where the model can tear (left empty otherwise).
void prepare_tearing(const Model& model, State& state);

// Breaks every intact bar past its limit at the positions state.x. While the energy is tracked,
// the elastic energy the broken springs held is booked as dissipated (it leaves as the fracture's
// heat and sound), so the energy balance still holds.
void break_overloaded_bars(const Model& model, State& state);

}  // namespace dinam
