#pragma once
// Which force kinds a step takes (each kind's switch, force_kind.hpp), and how a step may depart
// from the model's own motion.
#include <optional>

namespace dinam {

// Which force kinds act; each can be switched off so that a test isolates one.
struct ForceSwitches {
  bool gravity = true;
  bool fields = true;
  bool axial_springs = true;
  bool axial_dampers = true;
  bool bending = true;
  bool torsion = true;
  bool clamps = true;  // clamped supports' bending springs
  bool global_damping = true;
  bool wind = true;
  bool ground = true;
  bool object_contact = true;  // between objects and within one
  bool ties = true;            // attachments (`attach`)

  // Every kind off: a start from which to switch on one or two.
  static ForceSwitches none() {
    return {false, false, false, false, false, false, false, false, false, false, false, false};
  }
};

// How a step departs from the model's own motion without a copy of the model: the settling phase
// runs the scene's model with these (and with fields and wind switched off).
struct StepOptions {
  // 1/s, in place of model.global_damping (where ForceSwitches::global_damping leaves it on).
  std::optional<double> global_damping;
  // Driven pins stay where they are instead of following their paths (PinMotion).
  bool pins_hold_still = false;
  // The potential's forces alone, −∇V (compute_potential_forces): the ground gives its elastic
  // push without its damper and friction, so that neither the velocities nor the contact history
  // are read.
  bool elastic_only = false;
  // The bars as springs even in a model that holds them as constraints (`integrator: xpbd`,
  // stepped_switches): the settling phase relaxes to the model's equilibrium, which its bars'
  // springs define, at a step that they bound.
  bool bars_as_springs = false;
};

}  // namespace dinam
