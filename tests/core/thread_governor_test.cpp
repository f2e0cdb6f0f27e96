// The thread count that follows the machine: the decisions, stretch by stretch, from figures a
// test makes up (the step times and the kernel's counts are the run's; here the script's),
// and the readings of the kernel's files they rest on.
#include "core/thread_governor.hpp"

#include <gtest/gtest.h>

#include "core/cpu_share.hpp"
#include "core/machine_load.hpp"
#include "core/thread_team.hpp"

namespace dinam {
namespace {

// A machine of 2 CPUs on which one thread takes 1 ms a step whatever the load, and two take
// `two_threads` ms: the policy's count after `stretches` stretches at `others` CPUs busy.
struct Machine {
  double others = 0.0;
  double one_thread = 1.0;
  double two_threads = 0.55;
  int tried_other_counts = 0;

  int run(ThreadCountPolicy& policy, int count, int stretches) {
    for (int k = 0; k < stretches; ++k) {
      const int next = policy.next({count, count == 1 ? one_thread : two_threads, others});
      tried_other_counts += next != policy.settled() ? 1 : 0;
      count = next;
    }
    return count;
  }
};

TEST(ThreadCountPolicy, OnAnIdleMachineNothingIsTried) {
  ThreadCountPolicy policy(2, 2, 2);
  Machine idle;
  // Even where a stretch of two threads is slow now and then: without a load, nothing asks.
  for (int k = 0; k < 1000; ++k) {
    EXPECT_EQ(policy.next({2, k % 7 == 0 ? 2.0 : 0.55, 0.1}), 2);
  }
  EXPECT_EQ(idle.run(policy, 2, 1000), 2);
  EXPECT_EQ(idle.tried_other_counts, 0);
  // Nor where the kernel's counts cannot be read.
  EXPECT_EQ(policy.next({2, 5.0, std::nullopt}), 2);
  EXPECT_FALSE(policy.trying());
}

TEST(ThreadCountPolicy, ALoadedMachineGoesToOneThreadAndBackWhenItFrees) {
  ThreadCountPolicy policy(2, 2, 2);
  Machine machine;
  machine.others = 1.9;  // two busy processes: two threads wait on each other
  machine.two_threads = 6.0;
  int count = machine.run(policy, 2, 1);
  EXPECT_EQ(count, 1);  // tried
  count = machine.run(policy, count, 1);
  EXPECT_EQ(policy.settled(), 1);  // and kept: faster
  count = machine.run(policy, count, 50);
  EXPECT_EQ(count, 1);
  EXPECT_EQ(machine.tried_other_counts, 1);  // one thread's own load leaves no room for two

  machine.others = 0.05;  // they end
  machine.two_threads = 0.55;
  count = machine.run(policy, count, 2);
  EXPECT_EQ(policy.settled(), 2);
  EXPECT_EQ(count, 2);
}

TEST(ThreadCountPolicy, AFailedTrialWaitsEverLongerUntilTheLoadMoves) {
  ThreadCountPolicy policy(2, 2, 2);
  Machine machine;
  machine.others = 1.0;        // the load leaves room for one thread,
  machine.two_threads = 0.55;  // yet two stay faster (a model that shares well)
  int count = 2;
  std::vector<int> trials;
  for (int k = 0; k < 400; ++k) {
    const int next = policy.next({count, count == 1 ? 1.0 : 0.55, machine.others});
    if (next == 1) {
      trials.push_back(k);
    }
    count = next;
    EXPECT_EQ(policy.settled(), 2);
  }
  ASSERT_GE(trials.size(), 4u);
  // The gaps between trials double up to the longest wait.
  for (std::size_t t = 2; t < trials.size(); ++t) {
    EXPECT_GE(trials[t] - trials[t - 1], trials[t - 1] - trials[t - 2]);
    EXPECT_LE(trials[t] - trials[t - 1], ThreadCountPolicy::kMostWait + 2);
  }
  EXPECT_LE(trials.size(), 12u);  // 400 stretches: 1+2+4+…+64, then every 64
  // A load that moves by a CPU is a new machine: tried at once.
  EXPECT_EQ(policy.next({2, 0.55, 2.2}), 1);
}

TEST(ThreadCountPolicy, ALargeShareMovesStraightToTheRoomTheLoadLeaves) {
  ThreadCountPolicy policy(16, 16, 16);
  EXPECT_EQ(policy.next({16, 1.0, 9.8}), 6);  // 6.2 CPUs free
  EXPECT_EQ(policy.next({6, 0.8, 9.8}), 6);   // faster: kept
  EXPECT_EQ(policy.settled(), 6);
  EXPECT_EQ(policy.next({6, 0.8, 0.0}), 16);  // the others ended
  EXPECT_EQ(policy.next({16, 0.9, 0.0}), 6);  // slower: back
  EXPECT_EQ(policy.settled(), 6);
}

TEST(ThreadGovernor, AFixedCountIsLeftAsItIs) {
  int readings = 0;
  set_thread_policy(
      {2, 2, false, 2, "--threads 2"},
      [&] {
        ++readings;
        return std::optional<double>(2.0);
      },
      0.0);
  ThreadGovernor governor;
  for (int k = 0; k < 10; ++k) {
    governor.before_run();
    governor.after_run(100);
  }
  EXPECT_EQ(readings, 0);
  EXPECT_EQ(thread_count(), 2);
  EXPECT_EQ(governor.changes(), 0);
  set_thread_policy({1, 1, false, 1, "--threads 1"});
}

TEST(ThreadGovernor, TheProcessCountFollowsThePolicy) {
  set_thread_policy(
      {2, 2, true, 2, "own choice"}, [] { return std::optional<double>(1.9); }, 0.0);
  ThreadGovernor governor;
  governor.before_run();
  governor.after_run(100);
  EXPECT_EQ(thread_count(), 1);  // the trial
  EXPECT_EQ(governor.changes(), 1);
  set_thread_policy({1, 1, false, 1, "--threads 1"});
}

TEST(MachineLoad, ProcStatIsReadForTheCpusOfTheMask) {
  const std::string stat =
      "cpu  300 0 100 500 10 0 5 20 0 0\n"
      "cpu0 100 0 50 300 5 0 2 10 0 0\n"
      "cpu1 200 0 50 200 5 0 3 10 0 0\n"
      "cpu10 7 0 0 3 0 0 0 0 0 0\n"
      "intr 12345 0 0\n";
  const std::optional<CpuTicks> all = cpu_ticks(stat, {});
  ASSERT_TRUE(all);
  EXPECT_EQ(all->busy, 425u);  // user, system, softirq, steal
  EXPECT_EQ(all->total, 935u);
  const std::optional<CpuTicks> one = cpu_ticks(stat, {1});
  ASSERT_TRUE(one);
  EXPECT_EQ(one->busy, 263u);
  EXPECT_EQ(one->total, 468u);
  EXPECT_EQ(cpu_ticks(stat, {0, 10})->busy, 162u + 7u);
  EXPECT_FALSE(cpu_ticks(stat, {3}));
  EXPECT_FALSE(cpu_ticks("cpu0 x y\n", {0}));
}

TEST(MachineLoad, OthersAreTheBusyTimeLessThisProcesssOwn) {
  LoadSample before;
  before.wall_seconds = 10.0;
  before.own_cpu_seconds = 1.0;
  before.cpus = CpuTicks{1000, 5000};
  LoadSample after = before;
  after.wall_seconds += 0.5;
  after.own_cpu_seconds = 1.4;        // 0.4 s of ours in half a second
  after.cpus = CpuTicks{1150, 5100};  // 1.5 s busy of 2 CPUs' 1 s, at 100 ticks a second
  const std::optional<double> others = others_busy_cpus(before, after, 100);
  ASSERT_TRUE(others);
  EXPECT_NEAR(*others, (1.5 - 0.4) / 0.5, 1e-12);
  after.cpus = std::nullopt;
  EXPECT_FALSE(others_busy_cpus(before, after, 100));
}

TEST(MachineLoad, TheLoadAverageLineReadsItsRunnableTasks) {
  const std::optional<LoadAverage> load = parse_load_average("2.41 2.56 2.24 3/88 4800\n");
  ASSERT_TRUE(load);
  EXPECT_DOUBLE_EQ(load->one_minute, 2.41);
  EXPECT_EQ(load->runnable, 3);
  EXPECT_FALSE(parse_load_average("2.41 2.56 2.24 x/88 4800"));
  EXPECT_FALSE(parse_load_average("2.41 2.56"));
  EXPECT_FALSE(parse_load_average(""));
}

}  // namespace
}  // namespace dinam
