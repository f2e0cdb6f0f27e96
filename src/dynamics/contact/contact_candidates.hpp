#pragma once
// The broad phase of contact between objects and within one (object_contact.hpp).
//
// Candidates: every pair that could touch is found with a hash grid (contact_grid.hpp) of boxes
// grown by a skin s, and kept while no node of the scene's contact has moved by more than s since:
// the closest points of a pair are weighted means of its nodes, so a pair farther apart than
// reach + 2s when the candidates were found cannot have come within reach before then. Most steps
// check only the candidates; the search runs again once some node has moved by s. The pairs that
// touch are the same whenever the search ran and whatever the skin, so the motion depends on
// neither.
//
// The skin trades the two costs: a wider one finds more candidates to check every step, a
// narrower one searches more often. Each search sets it from the last interval, by counts alone
// (so that it is the same for any thread count and machine): a search costs about as much as
// checking kSearchCostInChecks candidates per primitive, and while the candidates checked since
// the last search cost more than the search, the skin narrows (to 1/20 of the largest radius at
// least); while they cost under a quarter of it, it widens again (to the largest radius at most).
// Falling cloth with little touching keeps the widest skin; cloth lying on itself, where every
// node has dozens of pairs within a radius, narrows it.
#include <vector>

#include "core/thread_team.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// Checking a candidate against searching again, per primitive (bar or node) of the contact;
// measured with bench_contact (bench/notes/performance.md).
inline constexpr double kSearchCostInChecks = 80.0;

// Finds the candidates again (state.object_contact.candidates, at the skin the last interval
// chose) when there are none yet, when some node has moved by the skin since they were found, or
// when checking them has cost more than a search with a narrower skin would.
void refresh_candidates(const Model& model, State& state);

// Sizes the search's arrays of one entry per bar, triangle or node (state.object_contact), so that
// a step allocates only as the pairs grow; nothing without contact between objects.
void prepare_object_contact(const Model& model, State& state);

// gather(item, list) for every item in [0, count), appending what it finds to `list`; in
// contiguous runs of items, one per member of the team, each into its own list of `per_thread`,
// which are then appended to `out` in order: the same elements in the same order for any thread
// count.
template <class Element, class Gather>
void gather_in_parallel(Index count, std::vector<std::vector<Element>>& per_thread,
                        std::vector<Element>& out, const Gather& gather) {
  if (count < kMinParallelItems) {
    for (Index i = 0; i < count; ++i) {
      gather(i, out);
    }
    return;
  }
  ThreadTeam& team = thread_team();
  if (per_thread.size() < static_cast<std::size_t>(team.size())) {
    per_thread.resize(static_cast<std::size_t>(team.size()));
  }
  team.run([&](const TeamMember& member) {
    std::vector<Element>& list = per_thread[static_cast<std::size_t>(member.index())];
    list.clear();
    const auto [first, last] = member.share(count);
    for (Index i = first; i < last; ++i) {
      gather(i, list);
    }
  });
  for (int m = 0; m < team.size(); ++m) {
    const std::vector<Element>& list = per_thread[static_cast<std::size_t>(m)];
    out.insert(out.end(), list.begin(), list.end());
  }
}

}  // namespace dinam
