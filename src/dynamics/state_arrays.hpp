#pragma once
// Every array of the State, listed once with what it holds (the idea of MuJoCo's mjxmacro.h):
// the settling phase's hand-over, the memory estimate's check and the threads test iterate this
// list, so an array added to state.hpp and here is handed over, counted and compared everywhere.
#include <concepts>
#include <string_view>
#include <type_traits>

#include "dynamics/state.hpp"

namespace dinam {

// What an array of the state holds, which decides who may ignore it.
enum class StateArrayRole {
  kMotion,   // positions and velocities: x_n and v_{n−½}
  kHistory,  // what the past leaves for the next step beside the motion: plastic sets, what has
             // broken, the ground's stick anchors. Settling hands these on to the run.
  kScratch,  // sized by the model, rewritten by every step (forces, the next x and v, the wind's
             // drag, the energy ledger, the contact's boxes)
  kPairs,    // contact between objects: the candidate and touching pairs, which grow with what
             // touches (so no estimate made before the run counts them exactly)
  kSharing,  // how the work is shared between the threads: differs with their number by design
};

template <typename T>
concept StateOrConstState = std::same_as<std::remove_const_t<T>, State>;

// visit(name, role, arrays...) for every std::vector of the states given (const or not, one or
// several of them side by side: the same array of each), in state.hpp's order. The lists each
// thread keeps are visited one by one for a single state, and only as the list of lists for
// several (their number differs with the threads). The contact grids' own arrays
// (contact_grid.hpp) are rebuilt from the boxes at every search and left out.
template <typename Visit, StateOrConstState... States>
void for_each_state_array(Visit&& visit, States&... states) {
  static_assert(sizeof...(States) >= 1);
  using enum StateArrayRole;
  visit(std::string_view("x"), kMotion, states.x...);
  visit(std::string_view("velocity"), kMotion, states.velocity...);
  visit(std::string_view("force"), kScratch, states.force...);
  visit(std::string_view("x_next"), kScratch, states.x_next...);
  visit(std::string_view("v_next"), kScratch, states.v_next...);
  visit(std::string_view("bar_lambda"), kScratch, states.bar_lambda...);
  visit(std::string_view("bar_projection"), kScratch, states.bar_projection...);

  visit(std::string_view("bar_plastic_set"), kHistory, states.bar_plastic_set...);
  visit(std::string_view("bend_plastic_set"), kHistory, states.bend_plastic_set...);
  visit(std::string_view("torsion_plastic_set"), kHistory, states.torsion_plastic_set...);
  visit(std::string_view("clamp_plastic_set"), kHistory, states.clamp_plastic_set...);
  visit(std::string_view("bar_broken"), kHistory, states.bar_broken...);
  visit(std::string_view("bend_broken"), kHistory, states.bend_broken...);
  visit(std::string_view("torsion_broken"), kHistory, states.torsion_broken...);
  visit(std::string_view("clamp_broken"), kHistory, states.clamp_broken...);
  visit(std::string_view("face_broken"), kHistory, states.face_broken...);
  visit(std::string_view("broken_bars"), kHistory, states.broken_bars...);
  visit(std::string_view("contact_anchor"), kHistory, states.contact_anchor...);
  visit(std::string_view("contact_touching"), kHistory, states.contact_touching...);
  visit(std::string_view("contact_sliding"), kHistory, states.contact_sliding...);

  visit(std::string_view("wind.node_wind"), kScratch, states.wind.node_wind...);
  visit(std::string_view("wind.item_force"), kScratch, states.wind.item_force...);

  visit(std::string_view("work_split.shares"), kSharing, states.work_split.shares...);
  visit(std::string_view("plastic_set_updates"), kSharing, states.plastic_set_updates...);
  if constexpr (sizeof...(States) == 1) {  // lists per thread, as many as the state's threads
    auto& state = (states, ...);
    for (auto& share : state.work_split.shares) {
      visit(std::string_view("work_split.bars"), kSharing, share.bars);
      visit(std::string_view("work_split.bends"), kSharing, share.bends);
      visit(std::string_view("work_split.torsions"), kSharing, share.torsions);
    }
    for (auto& updates : state.plastic_set_updates) {
      visit(std::string_view("plastic_set_updates[thread]"), kSharing, updates);
    }
    for (auto& candidates : state.object_contact.thread_candidates) {
      visit(std::string_view("object_contact.thread_candidates[thread]"), kSharing, candidates);
    }
    for (auto& touching : state.object_contact.thread_touching) {
      visit(std::string_view("object_contact.thread_touching[thread]"), kSharing, touching);
    }
  }

  visit(std::string_view("object_contact.candidates"), kPairs, states.object_contact.candidates...);
  visit(std::string_view("object_contact.reference_x"), kScratch,
        states.object_contact.reference_x...);
  visit(std::string_view("object_contact.thread_candidates"), kSharing,
        states.object_contact.thread_candidates...);
  visit(std::string_view("object_contact.thread_touching"), kSharing,
        states.object_contact.thread_touching...);
  visit(std::string_view("object_contact.touching"), kPairs, states.object_contact.touching...);
  visit(std::string_view("object_contact.previous"), kPairs, states.object_contact.previous...);
  visit(std::string_view("object_contact.bar_boxes"), kScratch, states.object_contact.bar_boxes...);
  visit(std::string_view("object_contact.triangle_boxes"), kScratch,
        states.object_contact.triangle_boxes...);
  visit(std::string_view("object_contact.bar_used"), kScratch, states.object_contact.bar_used...);
  visit(std::string_view("object_contact.object_bars_look"), kScratch,
        states.object_contact.object_bars_look...);
  visit(std::string_view("object_contact.triangle_used"), kScratch,
        states.object_contact.triangle_used...);

  visit(std::string_view("energy_workspace.damping"), kScratch, states.energy_workspace.damping...);
  visit(std::string_view("energy_workspace.contact_damping"), kScratch,
        states.energy_workspace.contact_damping...);
  visit(std::string_view("energy_workspace.friction"), kScratch,
        states.energy_workspace.friction...);
  visit(std::string_view("energy_workspace.wind"), kScratch, states.energy_workspace.wind...);
  visit(std::string_view("energy_workspace.field"), kScratch, states.energy_workspace.field...);
  visit(std::string_view("energy_workspace.v_whole"), kScratch, states.energy_workspace.v_whole...);
  visit(std::string_view("energy_workspace.bar_flow"), kScratch,
        states.energy_workspace.bar_flow...);
  visit(std::string_view("energy_workspace.bend_flow"), kScratch,
        states.energy_workspace.bend_flow...);
  visit(std::string_view("energy_workspace.torsion_flow"), kScratch,
        states.energy_workspace.torsion_flow...);
  visit(std::string_view("energy_workspace.clamp_flow"), kScratch,
        states.energy_workspace.clamp_flow...);
}

}  // namespace dinam
