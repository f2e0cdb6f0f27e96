// The thread count follows the share of the machine the process is given: --threads, then
// DINAM_THREADS, else the least of the affinity mask, the cgroup quota (rounded up) and
// SLURM_CPUS_PER_TASK. The cgroup files are read from a folder laid out as /sys/fs/cgroup is.
#include "core/cpu_share.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

void write(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

TEST(CpuShare, CpuMaxReadsAQuotaOverAPeriodAndNoneForMax) {
  EXPECT_EQ(cpu_max_quota("150000 100000\n"), 1.5);
  EXPECT_EQ(cpu_max_quota("200000 50000"), 4.0);
  EXPECT_FALSE(cpu_max_quota("max 100000\n").has_value());
  EXPECT_FALSE(cpu_max_quota("").has_value());
  EXPECT_FALSE(cpu_max_quota("-1 100000").has_value());
  EXPECT_FALSE(cpu_max_quota("150000 0").has_value());
}

// cgroup v2: the tightest `cpu.max` on the way from the process's cgroup up to the root.
TEST(CpuShare, TheTightestQuotaOfTheCgroupAndItsParentsCounts) {
  test::TemporaryFolder folder("cgroup-v2");
  const std::filesystem::path root = folder.path() / "cgroup";
  write(folder.path() / "self_cgroup", "0::/machine.slice/job.scope\n");
  write(root / "machine.slice/job.scope/cpu.max", "max 100000\n");
  write(root / "machine.slice/cpu.max", "250000 100000\n");
  CpuShare share = read_cpu_share(root, folder.path() / "self_cgroup");
  ASSERT_TRUE(share.quota_cpus.has_value());
  EXPECT_EQ(*share.quota_cpus, 2.5);
  EXPECT_EQ(share.quota_source, (root / "machine.slice/cpu.max").string());

  write(root / "machine.slice/job.scope/cpu.max", "50000 100000\n");
  write(root / "machine.slice/job.scope/cpu.stat", "nr_periods 40\nnr_throttled 10\n");
  share = read_cpu_share(root, folder.path() / "self_cgroup");
  EXPECT_EQ(*share.quota_cpus, 0.5);
  // How often the quota's group is throttled, read beside the quota.
  ASSERT_TRUE(share.throttled_share.has_value());
  EXPECT_EQ(*share.throttled_share, 0.25);

  // No quota anywhere, or no such files: none.
  write(folder.path() / "self_cgroup", "0::/elsewhere\n");
  EXPECT_FALSE(read_cpu_share(root, folder.path() / "self_cgroup").quota_cpus.has_value());
  EXPECT_FALSE(read_cpu_share(root, folder.path() / "missing").quota_cpus.has_value());
}

// cgroup v1: the cpu controller's quota over its period (-1: none).
TEST(CpuShare, AVersionOneQuotaCountsToo) {
  test::TemporaryFolder folder("cgroup-v1");
  const std::filesystem::path root = folder.path() / "cgroup";
  write(folder.path() / "self_cgroup", "7:memory:/job\n4:cpu,cpuacct:/job\n");
  write(root / "cpu,cpuacct/job/cpu.cfs_quota_us", "300000\n");
  write(root / "cpu,cpuacct/job/cpu.cfs_period_us", "100000\n");
  write(root / "cpu,cpuacct/cpu.cfs_quota_us", "-1\n");
  write(root / "cpu,cpuacct/cpu.cfs_period_us", "100000\n");
  const CpuShare share = read_cpu_share(root, folder.path() / "self_cgroup");
  ASSERT_TRUE(share.quota_cpus.has_value());
  EXPECT_EQ(*share.quota_cpus, 3.0);
}

TEST(CpuShare, TheLeastOfAffinityQuotaAndSlurmIsChosenAndSaidWhy) {
  CpuShare share;
  share.online_cpus = 16;
  share.affinity_cpus = 8;
  ThreadChoice choice = choose_threads(share, std::nullopt, nullptr);
  EXPECT_EQ(choice.threads, 8);
  EXPECT_NE(choice.reason.find("8 of the machine's 16 CPUs"), std::string::npos) << choice.reason;

  share.quota_cpus = 2.5;  // 2.5 CPUs of time run 3 threads
  share.quota_source = "/sys/fs/cgroup/job/cpu.max";
  choice = choose_threads(share, std::nullopt, nullptr);
  EXPECT_EQ(choice.threads, 3);
  EXPECT_NE(choice.reason.find("/sys/fs/cgroup/job/cpu.max"), std::string::npos);

  share.slurm_cpus = 2;
  choice = choose_threads(share, std::nullopt, nullptr);
  EXPECT_EQ(choice.threads, 2);
  EXPECT_NE(choice.reason.find("SLURM_CPUS_PER_TASK=2"), std::string::npos);

  share.quota_cpus = 0.2;  // a fifth of a CPU still runs one thread
  EXPECT_EQ(choose_threads(share, std::nullopt, nullptr).threads, 1);
}

// The start looks at the machine: the tasks runnable now take their share of this process's CPUs
// (all of them where the mask is the machine, a part where it is part), and what they leave is
// the count to start on, within the share; a run may then go back up to the share.
TEST(CpuShare, TheTasksRunnableNowLeaveTheCountToStartOn) {
  CpuShare share;
  share.online_cpus = 2;
  share.affinity_cpus = 2;
  const ThreadChoice idle = choose_threads(share, std::nullopt, nullptr, RunnableNow{0, 0.3});
  EXPECT_EQ(idle.threads, 2);
  EXPECT_EQ(idle.most, 2);
  EXPECT_TRUE(idle.adapts);
  EXPECT_NE(idle.reason.find("0 other tasks runnable now (load average 0.30), room for all"),
            std::string::npos)
      << idle.reason;
  for (const int others : {1, 2, 4}) {
    const ThreadChoice busy = choose_threads(share, std::nullopt, nullptr, RunnableNow{others, 2});
    EXPECT_EQ(busy.threads, 1) << others;
    EXPECT_EQ(busy.most, 2);
    EXPECT_NE(busy.reason.find("so 1 of 2"), std::string::npos) << busy.reason;
  }
  // 4 CPUs of a machine of 16, with 8 tasks runnable on it: 2 of them on ours, 2 left.
  share.online_cpus = 16;
  share.affinity_cpus = 4;
  EXPECT_EQ(choose_threads(share, std::nullopt, nullptr, RunnableNow{8, 8}).threads, 2);
  // The option and the variable are fixed, whatever the load.
  const ThreadChoice fixed = choose_threads(share, 3, nullptr, RunnableNow{8, 8});
  EXPECT_EQ(fixed.threads, 3);
  EXPECT_FALSE(fixed.adapts);
}

// A quota the group hits in many of its periods counts its whole CPUs only.
TEST(CpuShare, AThrottledQuotaCountsItsWholeCpus) {
  EXPECT_DOUBLE_EQ(*throttled_share("nr_periods 200\nnr_throttled 50\nthrottled_usec 9\n"), 0.25);
  EXPECT_FALSE(throttled_share("nr_periods 0\nnr_throttled 0\n"));
  EXPECT_FALSE(throttled_share("usage_usec 10\n"));
  CpuShare share;
  share.online_cpus = 8;
  share.affinity_cpus = 8;
  share.quota_cpus = 2.5;
  share.quota_source = "/sys/fs/cgroup/job/cpu.max";
  share.throttled_share = 0.05;
  EXPECT_EQ(choose_threads(share, std::nullopt, nullptr).threads, 3);
  share.throttled_share = 0.4;
  const ThreadChoice throttled = choose_threads(share, std::nullopt, nullptr);
  EXPECT_EQ(throttled.threads, 2);
  EXPECT_NE(throttled.reason.find("throttled in 40 % of its periods"), std::string::npos)
      << throttled.reason;
}

TEST(CpuShare, TheOptionThenTheVariableOverrideTheShare) {
  CpuShare share;
  share.affinity_cpus = 2;
  EXPECT_EQ(choose_threads(share, 6, "3").threads, 6);
  const ThreadChoice variable = choose_threads(share, std::nullopt, "3");
  EXPECT_EQ(variable.threads, 3);
  EXPECT_EQ(variable.reason, "DINAM_THREADS=3");
  for (const char* bad : {"", "two", "0", "-2", "2.5", "99999"}) {
    test::expect_user_error([&] { choose_threads(share, std::nullopt, bad); }, 0,
                            {"DINAM_THREADS", "whole number"});
  }
}

}  // namespace
}  // namespace dinam
