#include "model/step_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/frequency_bound.hpp"
#include "model/model.hpp"

namespace dinam {

StepLimits find_step_limits(const Model& model, std::size_t count) {
  StepLimits limits;
  const Index bars = model.bar_count();
  if (bars == 0) {
    return limits;
  }
  std::vector<BarLength> lengths(static_cast<std::size_t>(bars));
  for (Index b = 0; b < bars; ++b) {
    lengths[b] = {b, model.bar_rest_length[b]};
  }
  auto shorter = [](const BarLength& a, const BarLength& b) {
    return a.length < b.length || (a.length == b.length && a.bar < b.bar);
  };
  const std::size_t shown = std::min(count, lengths.size());
  std::vector<BarLength> by_length = lengths;
  std::partial_sort(by_length.begin(), by_length.begin() + static_cast<std::ptrdiff_t>(shown),
                    by_length.end(), shorter);
  limits.shortest.assign(by_length.begin(), by_length.begin() + static_cast<std::ptrdiff_t>(shown));
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end(), shorter);
  limits.median_length = middle->length;

  const NodeFrequencyRows rows = node_frequency_rows(model, true);
  const NodeFrequencyRows springs = node_frequency_rows(model, false);
  double highest = -1.0;
  for (std::size_t i = 0; i < rows.own.size(); ++i) {
    const double row = rows.own[i] + rows.coupling[i];
    if (!model.pinned(static_cast<Index>(i)) && row > highest) {
      highest = row;
      limits.fastest_node = static_cast<Index>(i);
    }
  }
  if (limits.fastest_node < 0) {
    return limits;
  }
  const auto node = static_cast<std::size_t>(limits.fastest_node);
  limits.fastest_node_omega = std::sqrt(highest);
  limits.contact_dominates = springs.own[node] + springs.coupling[node] < 0.5 * highest;
  limits.shortest_at_fastest = std::numeric_limits<double>::infinity();
  for (Index b = 0; b < bars; ++b) {
    if (model.bar_nodes[2 * b] == limits.fastest_node ||
        model.bar_nodes[2 * b + 1] == limits.fastest_node) {
      limits.shortest_at_fastest = std::min(limits.shortest_at_fastest, model.bar_rest_length[b]);
    }
  }
  return limits;
}

std::string describe_node(const Model& model, Index node) {
  const ModelObject& object = model.objects[model.node_object[node]];
  const Vec3& x = model.node_initial_x[node];
  return fmt::format("object '{}', node {} at ({:.4g}, {:.4g}, {:.4g}) m", object.name,
                     node - object.first_node, x.x(), x.y(), x.z());
}

}  // namespace dinam
