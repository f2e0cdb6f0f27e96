#pragma once
// What the tests of every force kind share (spring_kinds_test.cpp, stiffness_test.cpp): a small
// model that has every kind of spring, moved off its rest shape, and switches with nothing on.
#include <random>
#include <string>

#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam::test {

// Every force switched off: a test switches on the kind it isolates.
inline ForceSwitches nothing_on() {
  ForceSwitches switches;
  switches.gravity = switches.fields = switches.axial_springs = switches.axial_dampers = false;
  switches.bending = switches.torsion = switches.clamps = switches.global_damping = false;
  switches.wind = switches.ground = switches.object_contact = switches.ties = false;
  return switches;
}

// A wire lattice of 5 × 5 cells of 0.2 m hanging from a clamped edge (so clamps exist beside
// axial, bending and torsion springs), and a cord 5 cm beside it tied to it (ties), every free
// node moved by up to 3 mm at random and 4 mm down, so that its lowest row, 2 mm above the
// ground, dips into it. `material_extra` ends the
// material's map (", yield_stress: 1.0e6").
struct PerturbedLattice {
  Model model;
  State state;
};

inline PerturbedLattice perturbed_lattice(const std::string& material_extra = "") {
  PerturbedLattice p{build_model(scene_from_yaml(R"(version: 1
duration: 1
ground: {height: -0.3}
objects:
  - name: lattice
    mesh:
      grid: {width: 1.0, height: 1.0, columns: 5, rows: 5, diagonals: none}
      rotation: [-90, 0, 0]
      translation: [0, 0, 0.702]
    material: {density: 7850, youngs_modulus: 2.0e9, radius: 0.002)" +
                                                 material_extra + R"(}
    pinned: {box: {min: [-1, -1, 0.701], max: [1, 1, 0.703]}, clamped: true}
  - name: cord
    mesh: {polyline: {points: [[0.1, 0.05, 0.1], [0.9, 0.05, 0.1]], segments: 4}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.002}
    attach: [{nodes: {all: true}, to: lattice, stiffness: 500}]
)")),
                     {}};
  p.state = make_state(p.model, false);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-0.003, 0.003);
  for (Index i = 0; i < p.model.node_count(); ++i) {
    if (!p.model.pinned(i)) {
      p.state.x[i] += Vec3(offset(random), offset(random), offset(random) - 0.004);
    }
  }
  return p;
}

}  // namespace dinam::test
