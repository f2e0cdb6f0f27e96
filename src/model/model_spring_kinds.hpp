#pragma once
// Every kind of spring as the model stage knows it, in the order a step adds their forces
// (dynamics/spring_kinds.hpp lists their kernels in the same order, which a test checks). The
// stability bound sums their terms in this order, so the order is part of the step's bits.
#include <array>

#include "model/model_spring_kind.hpp"

namespace dinam {

extern const ModelSpringKind kAxialSpringModel;
extern const ModelSpringKind kBendingSpringModel;
extern const ModelSpringKind kClampModel;
extern const ModelSpringKind kTorsionSpringModel;

inline constexpr std::array<const ModelSpringKind*, 4> kModelSpringKinds{
    &kAxialSpringModel, &kBendingSpringModel, &kClampModel, &kTorsionSpringModel};

}  // namespace dinam
