#include "model/plausibility.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "model/model.hpp"

namespace dinam {

namespace {

// Larger than any such thing is made: a sheet (a cloth, a sail) over 50 m across, or anything
// else over a kilometre, read from a mesh file, is a file in centimetres or millimetres read as
// metres (a 1.2 m curtain modelled in centimetres is a 120 m, 1 728 kg one).
constexpr double kLargestSheet = 50.0;    // m across
constexpr double kLargestOther = 1000.0;  // m across: a rope, a cable, a net

void note_implausible_size(const SceneDescription& scene, const Model& model, std::size_t o,
                           std::vector<std::string>& warnings) {
  const ModelObject& object = model.objects[o];
  const ObjectDesc& desc = scene.objects[o];
  if (desc.mesh_source.rfind("mesh file", 0) != 0 || object.node_count == 0) {
    return;  // a generated mesh is in metres by construction
  }
  Vec3 low = model.node_initial_x[object.first_node];
  Vec3 high = low;
  double mass = 0.0;
  for (Index i = object.first_node; i < object.first_node + object.node_count; ++i) {
    low = low.cwiseMin(model.node_initial_x[i]);
    high = high.cwiseMax(model.node_initial_x[i]);
    mass += model.node_mass[i];
  }
  const double across = (high - low).norm();
  const bool sheet = desc.material.sheet.has_value();
  const double largest = sheet ? kLargestSheet : kLargestOther;
  if (across <= largest) {
    return;
  }
  // An object pinned whole (a collider) has no mass that matters: its size alone tells the slip.
  const std::string weight = desc.pins.all ? "" : fmt::format(" and weighs {:.4g} kg", mass);
  warnings.push_back(fmt::format(
      "{}: warning: object '{}': its {} is {:.4g} m across{}, larger than {} is made ({:g} m); a "
      "mesh file is read in metres: if it was modelled in centimetres or millimetres, give its "
      "mesh 'units: cm' (or mm), or 'fit: {{size: …}}' for the size wanted",
      desc.mesh_loc.known() ? desc.mesh_loc.to_string() : "dinam", object.name, desc.mesh_source,
      across, weight, sheet ? "any cloth" : "any rope or cable", largest));
}

}  // namespace

void note_implausible_values(const SceneDescription& scene, Model& model) {
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    note_implausible_size(scene, model, o, model.warnings);
    const ModelObject& object = model.objects[o];
    if (object.wire_radius <= 0.0 || object.bar_count == 0 || scene.objects[o].pins.all) {
      continue;  // a section given by its area, or pinned whole: no radius that matters
    }
    // A bar is a slender rod: one thicker than it is long has a radius in the wrong unit.
    std::vector<double> lengths(
        model.bar_rest_length.begin() + object.first_bar,
        model.bar_rest_length.begin() + object.first_bar + object.bar_count);
    const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    if (object.wire_radius <= *middle) {
      continue;
    }
    double mass = 0.0;
    for (Index i = object.first_node; i < object.first_node + object.node_count; ++i) {
      mass += model.node_mass[i];
    }
    const FileLoc& loc = scene.objects[o].material.loc;
    model.warnings.push_back(fmt::format(
        "{}: warning: object '{}': its wire radius, {:g} m, is larger than its bars (the median "
        "is {:.3g} m long), which makes it {:.4g} kg; 'radius' is in metres (1 mm is 0.001)",
        loc.known() ? loc.to_string() : "dinam", object.name, object.wire_radius, *middle, mass));
  }
}

}  // namespace dinam
