#pragma once
// Edge collapse: the ends of a mesh's very short bars become one node before the model is built
// (`mesh: {weld}`). A sliver edge a modelling tool left behind is stiff (EA/L) on nodes whose mass
// the long bars set, so alone it would set a time step many times shorter than the rest needs.
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "model/vertex_welding.hpp"

namespace dinam {

struct EdgeCollapse {
  WeldResult weld;             // the welding with the collapsed ends merged
  Index merged_nodes = 0;      // nodes that joined another
  double tolerance = 0.0;      // m: bars shorter than this were collapsed
  double median_length = 0.0;  // m, of the bars before collapsing
};

// Merges the ends of the bars (`edges`, welded ids) shorter than `fraction` × their median length,
// shortest first, in passes until none is left. Only bar ends merge, so no two parts that no bar
// joins are joined; in one pass a merged group reaches at most the tolerance from its first node,
// which keeps its place, so a finely divided curve shortens by a few bars a pass instead of
// being drawn into a point. Ids follow first occurrence, as in weld_vertices.
EdgeCollapse collapse_short_edges(const WeldResult& weld,
                                  const std::vector<std::pair<Index, Index>>& edges,
                                  double fraction);

}  // namespace dinam
