#pragma once
// Tears in the pictures: a bar that broke in the simulation (dynamics/tearing.hpp) is no longer
// drawn from the first frame that shows it broken, nor is any surface triangle it is an edge of.
#include <vector>

#include "core/types.hpp"
#include "render/draw_list.hpp"

namespace dinam {

struct Model;
struct State;

// A bar that broke, by its end nodes, and the first frame that shows it broken.
struct TornBar {
  int frame = 1;
  Index n0 = 0;
  Index n1 = 0;
};

// Appends to `tears` the bars that broke since it was last brought up to date (state.broken_bars
// holds them in order), as shown first at `frame`.
void record_tears(const Model& model, const State& state, int frame, std::vector<TornBar>& tears);

// Hides the bar in `list`: its segment gets radius 0 and every triangle with it as an edge
// collapses to a point (a quad's other triangle stays). The caller gives the list a new revision.
void hide_torn_bar(const TornBar& bar, DrawList& list);

}  // namespace dinam
