#include "model/wind_load.hpp"

#include <algorithm>
#include <numbers>
#include <random>

#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

std::array<TurbulenceWave, 3 * kTurbulenceWaves> make_turbulence_waves(std::uint32_t seed,
                                                                       double scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> spread(0.5, 1.5);
  std::array<TurbulenceWave, 3 * kTurbulenceWaves> waves{};
  for (int i = 0; i < 3 * kTurbulenceWaves; ++i) {
    // Three draws for the direction, then the magnitude, then the phase: the order of the draws
    // is what makes a seed's wind, so it must not change.
    Vec3 direction(unit(rng), unit(rng), unit(rng));
    direction.normalize();
    const double magnitude = 2.0 * std::numbers::pi / scale * spread(rng);
    TurbulenceWave& wave = waves[static_cast<std::size_t>(i)];
    wave.wavenumber = magnitude * direction;
    wave.phase = std::numbers::pi * unit(rng);
    wave.drift = 0.7 * (i % kTurbulenceWaves + 1);
  }
  return waves;
}

namespace {

// The nodes of the wind's faces and bars, and each node's items (WindLoad::node_items), by a
// counting sort of (node, item) pairs: items are visited in ascending order, so each node's list
// comes out ascending.
void list_nodes_and_their_items(Model& model) {
  WindLoad& wind = model.wind;
  const auto face_count = static_cast<Index>(wind.faces.size());
  std::vector<Index> per_node(static_cast<std::size_t>(model.node_count()) + 1, 0);
  auto for_each_pair = [&](const auto& visit) {
    for (Index s = 0; s < face_count; ++s) {
      const Index f = wind.faces[s];
      for (Index k = model.face_offsets[f]; k < model.face_offsets[f + 1]; ++k) {
        visit(model.face_nodes[k], s);
      }
    }
    for (Index s = 0; s < static_cast<Index>(wind.bars.size()); ++s) {
      const Index b = wind.bars[s];
      visit(model.bar_nodes[2 * b], face_count + s);
      visit(model.bar_nodes[2 * b + 1], face_count + s);
    }
  };
  for_each_pair([&](Index node, Index) { ++per_node[node + 1]; });
  std::vector<Index> slot(per_node.size(), -1);  // each node's place in wind.nodes
  wind.node_item_offsets.push_back(0);
  for (Index node = 0; node < model.node_count(); ++node) {
    if (per_node[node + 1] > 0) {
      slot[node] = static_cast<Index>(wind.nodes.size());
      wind.nodes.push_back(node);
      wind.node_item_offsets.push_back(wind.node_item_offsets.back() + per_node[node + 1]);
    }
  }
  wind.node_items.resize(static_cast<std::size_t>(wind.node_item_offsets.back()));
  std::vector<Index> next(wind.node_item_offsets.begin(), wind.node_item_offsets.end() - 1);
  for_each_pair([&](Index node, Index item) { wind.node_items[next[slot[node]]++] = item; });
}

}  // namespace

void add_wind(const SceneDescription& scene, Model& model) {
  model.wind.field = scene.wind;
  if (!scene.wind.enabled) {
    return;
  }
  auto feels_wind = [&](Index object) {
    const auto& names = scene.wind.objects;
    return names.empty() ||
           std::find(names.begin(), names.end(), model.objects[object].name) != names.end();
  };
  // Faces take pressure drag; a bar on no face is a bare wire and takes cross-flow drag.
  for (Index f = 0; f < model.face_count(); ++f) {
    if (feels_wind(model.node_object[model.face_nodes[model.face_offsets[f]]])) {
      model.wind.faces.push_back(f);
    }
  }
  for (Index b = 0; b < model.bar_count(); ++b) {
    if (model.bar_on_face[b] == 0 && feels_wind(model.node_object[model.bar_nodes[2 * b]])) {
      model.wind.bars.push_back(b);
    }
  }
  list_nodes_and_their_items(model);
  if (scene.wind.turbulence != 0.0) {
    model.wind.waves = make_turbulence_waves(scene.wind.seed, scene.wind.turbulence_scale);
  }
}

}  // namespace dinam
