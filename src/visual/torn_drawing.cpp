#include "visual/torn_drawing.hpp"

#include "dynamics/state.hpp"
#include "model/model.hpp"

namespace dinam {

void record_tears(const Model& model, const State& state, int frame, std::vector<TornBar>& tears) {
  for (std::size_t k = tears.size(); k < state.broken_bars.size(); ++k) {
    const Index bar = state.broken_bars[k];
    tears.push_back({frame, model.bar_nodes[2 * bar], model.bar_nodes[2 * bar + 1]});
  }
}

void hide_torn_bar(const TornBar& bar, DrawList& list) {
  auto is_bar = [&](Index a, Index b) {
    return (a == bar.n0 && b == bar.n1) || (a == bar.n1 && b == bar.n0);
  };
  for (std::size_t s = 0; s < list.segment_radius.size(); ++s) {
    if (is_bar(list.segment_points[2 * s], list.segment_points[2 * s + 1])) {
      list.segment_radius[s] = 0.0f;
    }
  }
  for (SurfaceBatch& batch : list.surfaces) {
    std::vector<Index>& t = batch.triangles;
    for (std::size_t k = 0; k + 2 < t.size(); k += 3) {
      if (is_bar(t[k], t[k + 1]) || is_bar(t[k + 1], t[k + 2]) || is_bar(t[k + 2], t[k])) {
        t[k + 1] = t[k + 2] = t[k];
      }
    }
  }
}

}  // namespace dinam
