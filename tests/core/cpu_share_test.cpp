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
  share = read_cpu_share(root, folder.path() / "self_cgroup");
  EXPECT_EQ(*share.quota_cpus, 0.5);

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
