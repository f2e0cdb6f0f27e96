#include "core/thread_team.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace dinam {
namespace {

// How long a waiting member spins before it sleeps. At a barrier inside a step the wait on an
// idle machine is the imbalance between the members' shares, a few microseconds, far below the
// cost of sleeping and being woken (tens of microseconds on a virtual machine whose idle core
// halts); a wait longer than this means the member waited for is not running (another process
// has its core), and spinning on would only burn the time slice that process leaves us.
constexpr std::chrono::microseconds kBarrierSpin{50};
// Between jobs a worker spins a little longer: the calling thread's work between two steps
// (the checks, the energy report) is short, and the next step should not have to wake anyone.
constexpr std::chrono::microseconds kIdleSpin{200};

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

// Returns once `value` differs from `old`: spinning for up to `spin`, then sleeping on it.
template <class T>
void wait_until_changed(const std::atomic<T>& value, T old, std::chrono::microseconds spin) {
  const auto start = std::chrono::steady_clock::now();
  for (unsigned round = 1;; ++round) {
    if (value.load(std::memory_order_acquire) != old) {
      return;
    }
    cpu_relax();
    if (round % 64 == 0 && std::chrono::steady_clock::now() - start > spin) {
      break;
    }
  }
  while (value.load(std::memory_order_acquire) == old) {
    value.wait(old, std::memory_order_acquire);
  }
}

struct ProcessTeam {
  int threads = 1;
  std::unique_ptr<ThreadTeam> team;
};

ProcessTeam& process_team() {
  static ProcessTeam team;
  return team;
}

}  // namespace

void TeamMember::barrier_then(void (*completion)(const void*), const void* argument) const {
  if (team_ != nullptr && count_ > 1) {
    team_->arrive_at_barrier(completion, argument);
  } else if (completion != nullptr) {
    completion(argument);
  }
}

void ThreadTeam::arrive_at_barrier(void (*completion)(const void*), const void* argument) const {
  // The phase is read before arriving: the last member to arrive advances it only after every
  // member has arrived, so a member never waits on a phase that has already passed.
  const std::uint32_t phase = barrier_phase_.load(std::memory_order_acquire);
  if (arrived_.fetch_add(1, std::memory_order_acq_rel) == size_ - 1) {
    if (completion != nullptr) {
      completion(argument);
    }
    arrived_.store(0, std::memory_order_relaxed);
    barrier_phase_.fetch_add(1, std::memory_order_release);
    barrier_phase_.notify_all();
    return;
  }
  wait_until_changed(barrier_phase_, phase, kBarrierSpin);
}

ThreadTeam::ThreadTeam(int threads) : size_(std::max(1, threads)) {
  workers_.reserve(static_cast<std::size_t>(size_ - 1));
  for (int index = 1; index < size_; ++index) {
    workers_.emplace_back([this, index] { work(index); });
  }
}

ThreadTeam::~ThreadTeam() {
  stopping_ = true;
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  for (std::thread& worker : workers_) {
    worker.join();
  }
}

void ThreadTeam::run_erased(Invoke invoke, const void* job) {
  invoke_ = invoke;
  job_ = job;
  finished_.store(0, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  invoke(job, TeamMember(this, 0, size_));
  // Every worker counts itself done, so none can still be reading this job when the next starts.
  for (int done = finished_.load(std::memory_order_acquire); done != size_ - 1;
       done = finished_.load(std::memory_order_acquire)) {
    wait_until_changed(finished_, done, kBarrierSpin);
  }
}

void ThreadTeam::work(int index) {
  std::uint32_t seen = 0;
  for (;;) {
    wait_until_changed(generation_, seen, kIdleSpin);
    seen = generation_.load(std::memory_order_acquire);
    if (stopping_) {
      return;
    }
    invoke_(job_, TeamMember(this, index, size_));
    worker_jobs_.fetch_add(1, std::memory_order_relaxed);
    finished_.fetch_add(1, std::memory_order_acq_rel);
    finished_.notify_one();
  }
}

ThreadTeam& thread_team() {
  ProcessTeam& process = process_team();
  if (!process.team) {
    process.team = std::make_unique<ThreadTeam>(process.threads);
  }
  return *process.team;
}

int thread_count() {
  return process_team().threads;
}

void set_thread_count(int threads) {
  ProcessTeam& process = process_team();
  threads = std::max(1, threads);
  if (process.team && process.team->size() == threads) {
    return;
  }
  process.team.reset();
  process.threads = threads;
}

}  // namespace dinam
