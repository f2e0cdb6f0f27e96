#pragma once
// A frame's regions of the tolerance file (snapshot/tolerance_file.hpp) as one weight per pixel:
// 1 where no region lies, 0 where one is ignored, a region's weight where it is weighed more (the
// largest where weighed regions overlap; an ignored one wins over any).
#include <vector>

#include "render/draw_list.hpp"
#include "snapshot/tolerance_file.hpp"

namespace dinam {

// Empty when there are no regions (every pixel 1). A box of the scene covers the rectangle that
// holds the projections of its corners in front of `camera`; a box wholly behind it covers none.
std::vector<float> region_weights(const std::vector<SnapshotRegion>& regions, int width, int height,
                                  const RenderCamera& camera);

}  // namespace dinam
