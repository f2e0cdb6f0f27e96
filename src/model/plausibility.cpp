#include "model/plausibility.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "model/model.hpp"

namespace dinam {

void note_implausible_values(const SceneDescription& scene, Model& model) {
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ModelObject& object = model.objects[o];
    if (object.wire_radius <= 0.0 || object.bar_count == 0) {
      continue;  // a section given by its area: no radius to compare
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
