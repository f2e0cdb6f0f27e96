// The thread team runs a job on every member, each once, and its barriers order what the members
// write: after a barrier every member sees what every other wrote before it, and a barrier's
// completion runs once, between the two sides.
#include "core/thread_team.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <numeric>
#include <vector>

namespace dinam {
namespace {

TEST(ThreadTeam, AJobRunsOnceOnEveryMember) {
  for (const int size : {1, 2, 3, 5}) {
    ThreadTeam team(size);
    std::vector<int> runs(static_cast<std::size_t>(size), 0);
    std::atomic<int> count_seen{0};
    for (int job = 0; job < 100; ++job) {
      team.run([&](const TeamMember& member) {
        runs[static_cast<std::size_t>(member.index())] += 1;
        if (member.count() == size) {
          count_seen.fetch_add(1);
        }
      });
    }
    for (const int r : runs) {
      EXPECT_EQ(r, 100) << size << " threads";
    }
    EXPECT_EQ(count_seen.load(), 100 * size);
    // Alone: only the calling thread, as the solo member.
    int alone = 0;
    team.run([&](const TeamMember& member) { alone += member.count() == 1 ? 1 : 100; }, true);
    EXPECT_EQ(alone, 1);
  }
}

// Each phase every member writes its own slot, meets the others, then reads them all: a member
// that ran ahead of a barrier, or a write that is not visible after it, shows as a wrong sum.
TEST(ThreadTeam, BarriersOrderTheMembersWrites) {
  constexpr int kSize = 3;
  constexpr int kPhases = 20000;
  ThreadTeam team(kSize);
  std::vector<long> slot(kSize, 0);
  std::vector<long> wrong(kSize, 0);
  long completions = 0;
  team.run([&](const TeamMember& member) {
    for (long phase = 1; phase <= kPhases; ++phase) {
      slot[static_cast<std::size_t>(member.index())] = phase * (member.index() + 1);
      member.barrier([&] { ++completions; });
      const long sum = std::accumulate(slot.begin(), slot.end(), 0L);
      wrong[static_cast<std::size_t>(member.index())] += sum != phase * 6 ? 1 : 0;
      member.barrier();  // nobody writes the next phase's slot before all have read this one
    }
  });
  for (const long w : wrong) {
    EXPECT_EQ(w, 0);
  }
  EXPECT_EQ(completions, kPhases);
}

TEST(ThreadTeam, SharesCoverARangeInOrderCutAtTheGrain) {
  for (const int count : {1, 2, 3, 7}) {
    for (const Index n : {0, 1, 5, 64, 1000, 1003}) {
      Index next = 0;
      for (int m = 0; m < count; ++m) {
        const auto [first, last] = TeamMember(nullptr, m, count).share(n, 8);
        EXPECT_EQ(first, next);
        EXPECT_LE(first, last);
        EXPECT_TRUE(first % 8 == 0 || first == n);
        next = last;
      }
      EXPECT_EQ(next, n);
    }
  }
}

TEST(ThreadTeam, TheProcessTeamTakesTheCountSet) {
  const int before = thread_count();
  set_thread_count(3);
  EXPECT_EQ(thread_team().size(), 3);
  set_thread_count(0);  // at least one
  EXPECT_EQ(thread_team().size(), 1);
  set_thread_count(before);
}

}  // namespace
}  // namespace dinam
