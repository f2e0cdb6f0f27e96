#pragma once
// The stick spring of Coulomb friction inside an implicit step, as a potential of its stretch u
// (ground_friction_implicit.hpp for the ground, object_contact_implicit.hpp between objects): k u
// up to the cap μN, beyond which it slides at the cap,
//   E(u) = ½ k |u|²  for |u| ≤ r_c = μN/k,   μN (|u| − r_c) + ½ k r_c²  beyond,
// convex and once differentiable.
#include "core/types.hpp"

namespace dinam {

// E at |u| = r, J.
inline double capped_spring_energy(double k, double cap, double r) {
  const double reach = cap / k;  // r_c
  return r <= reach ? 0.5 * k * r * r : cap * (r - reach) + 0.5 * k * reach * reach;
}

// ∇E at u, N.
inline Vec3 capped_spring_gradient(double k, double cap, const Vec3& u) {
  const double r = u.norm();
  return r * k <= cap ? Vec3(k * u) : Vec3((cap / r) * u);
}

// ∇²E at u within the plane `across` projects onto (u lies in it): sticking k P; sliding the
// cap's force turning with u, (μN/r)(P − û ûᵀ), positive semi-definite (nothing along û: the
// force's size does not change with r).
inline Mat3 capped_spring_hessian(double k, double cap, const Vec3& u, const Mat3& across) {
  const double r = u.norm();
  if (r * k > cap) {
    const Vec3 along = u / r;
    return (cap / r) * (across - along * along.transpose());
  }
  return k * across;
}

}  // namespace dinam
