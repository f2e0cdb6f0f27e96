#pragma once
// Every array of the Model, listed once (the idea of MuJoCo's mjxmacro.h): what gives spare
// capacity back, counts the model's bytes or compares two models iterates this list, so an array
// added to model.hpp and here is released, counted and compared everywhere.
#include <concepts>
#include <string_view>
#include <type_traits>

#include "model/model.hpp"

namespace dinam {

template <typename T>
concept ModelOrConstModel = std::same_as<std::remove_const_t<T>, Model>;

// visit(name, array) for every std::vector of numbers in `model` (const or not), in model.hpp's
// order; the vectors of a field's or a pin motion's nodes once per field or motion. The model's
// names and warnings (strings) are not arrays of the model's numbers and are left out.
template <ModelOrConstModel ModelType, typename Visit>
void for_each_model_array(ModelType& model, Visit&& visit) {
  visit(std::string_view("node_initial_x"), model.node_initial_x);
  visit(std::string_view("node_initial_v"), model.node_initial_v);
  visit(std::string_view("node_mass"), model.node_mass);
  visit(std::string_view("node_inv_mass"), model.node_inv_mass);
  visit(std::string_view("node_object"), model.node_object);
  visit(std::string_view("node_uv"), model.node_uv);
  visit(std::string_view("node_source_vertex"), model.node_source_vertex);

  visit(std::string_view("bar_nodes"), model.bar_nodes);
  visit(std::string_view("bar_rest_length"), model.bar_rest_length);
  visit(std::string_view("bar_axial_stiffness"), model.bar_axial_stiffness);
  visit(std::string_view("bar_yield_force"), model.bar_yield_force);
  visit(std::string_view("bar_damping"), model.bar_damping);
  visit(std::string_view("bar_radius"), model.bar_radius);
  visit(std::string_view("bar_on_face"), model.bar_on_face);
  visit(std::string_view("bar_sweep_order"), model.bar_sweep_order);

  visit(std::string_view("bend_nodes"), model.bend_nodes);
  visit(std::string_view("bend_rest_angle"), model.bend_rest_angle);
  visit(std::string_view("bend_stiffness"), model.bend_stiffness);
  visit(std::string_view("bend_yield_moment"), model.bend_yield_moment);

  visit(std::string_view("torsion_nodes"), model.torsion_nodes);
  visit(std::string_view("torsion_rest_angle"), model.torsion_rest_angle);
  visit(std::string_view("torsion_stiffness"), model.torsion_stiffness);
  visit(std::string_view("torsion_yield_moment"), model.torsion_yield_moment);

  visit(std::string_view("clamp_nodes"), model.clamp_nodes);
  visit(std::string_view("clamp_ghost_offset"), model.clamp_ghost_offset);
  visit(std::string_view("clamp_stiffness"), model.clamp_stiffness);
  visit(std::string_view("clamp_yield_moment"), model.clamp_yield_moment);

  visit(std::string_view("bar_breaking_strain"), model.bar_breaking_strain);
  visit(std::string_view("bar_breaking_force"), model.bar_breaking_force);
  visit(std::string_view("bar_spring_offsets"), model.bar_spring_offsets);
  visit(std::string_view("bar_springs"), model.bar_springs);
  visit(std::string_view("bar_face_offsets"), model.bar_face_offsets);
  visit(std::string_view("bar_faces"), model.bar_faces);

  visit(std::string_view("face_offsets"), model.face_offsets);
  visit(std::string_view("face_nodes"), model.face_nodes);
  visit(std::string_view("face_uv"), model.face_uv);
  visit(std::string_view("face_origin"), model.face_origin);

  for (auto& field : model.fields) {
    visit(std::string_view("fields.nodes"), field.nodes);
  }
  for (auto& motion : model.pin_motions) {
    visit(std::string_view("pin_motions.nodes"), motion.nodes);
    visit(std::string_view("pin_motions.track"), motion.track);
  }

  visit(std::string_view("wind.faces"), model.wind.faces);
  visit(std::string_view("wind.bars"), model.wind.bars);
  visit(std::string_view("wind.nodes"), model.wind.nodes);
  visit(std::string_view("wind.node_item_offsets"), model.wind.node_item_offsets);
  visit(std::string_view("wind.node_items"), model.wind.node_items);

  visit(std::string_view("ground.node_stiffness"), model.ground.node_stiffness);
  visit(std::string_view("ground.node_damping"), model.ground.node_damping);
  visit(std::string_view("ground.node_radius"), model.ground.node_radius);

  visit(std::string_view("contact.object_between"), model.contact.object_between);
  visit(std::string_view("contact.object_self"), model.contact.object_self);
  visit(std::string_view("contact.bars"), model.contact.bars);
  visit(std::string_view("contact.bar_radius"), model.contact.bar_radius);
  visit(std::string_view("contact.points"), model.contact.points);
  visit(std::string_view("contact.point_radius"), model.contact.point_radius);
  visit(std::string_view("contact.triangles"), model.contact.triangles);
  visit(std::string_view("contact.triangle_face"), model.contact.triangle_face);
  visit(std::string_view("contact.triangle_radius"), model.contact.triangle_radius);
  visit(std::string_view("contact.neighbour_offsets"), model.contact.neighbour_offsets);
  visit(std::string_view("contact.neighbours"), model.contact.neighbours);
  visit(std::string_view("contact.tied_bar_pairs"), model.contact.tied_bar_pairs);
  visit(std::string_view("contact.tied_point_triangles"), model.contact.tied_point_triangles);

  visit(std::string_view("ties.nodes"), model.ties.nodes);
  visit(std::string_view("ties.weights"), model.ties.weights);
  visit(std::string_view("ties.offset"), model.ties.offset);
  visit(std::string_view("ties.rest_length"), model.ties.rest_length);
  visit(std::string_view("ties.stiffness"), model.ties.stiffness);
  visit(std::string_view("ties.rigid"), model.ties.rigid);
  visit(std::string_view("ties.break_force"), model.ties.break_force);
}

}  // namespace dinam
