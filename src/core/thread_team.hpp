#pragma once
// The threads that share a step's work: a fixed team, started once, that runs one job at a time
// on every member, the calling thread being member 0. Inside a job the members split loops into
// fixed ranges and meet at barriers (between the colours of the springs, dynamics/
// parallel_loops.hpp); a whole step is one job, so a step wakes the team once.
//
// Why not OpenMP's threads: a thread of libgomp that waits (at a barrier, at the end of a
// parallel region, for the next region) spins for 300 000 rounds before it sleeps, a policy read
// once from the environment when the library loads (GOMP_SPINCOUNT, OMP_WAIT_POLICY) that the
// program cannot change. On a machine that other work shares, the thread it waits for is often
// not running, and the spinning one burns the time slice that thread needs: a step of 5 750 bars
// on 2 threads went from 0.21 ms to 295 ms with one busy process per core
// (bench/notes/performance.md, "Threads on a shared machine"). Here a waiting thread spins only for
// a few tens of microseconds, long enough for the usual wait on an idle machine (where falling
// asleep and waking cost more than the wait), then sleeps on a futex until it is released. OpenMP
// stays for what it does well: `omp simd` in the kernels.
#include <atomic>
#include <cstdint>
#include <thread>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace dinam {

class ThreadTeam;

// One thread's part in a job: which member it is and of how many, its share of a loop, and the
// barrier where the members meet.
class TeamMember {
 public:
  TeamMember(const ThreadTeam* team, int index, int count)
      : team_(team), index_(index), count_(count) {}

  int index() const { return index_; }
  int count() const { return count_; }
  // Member 0, which runs the work that must be done once (serial stages, the checks).
  bool leader() const { return index_ == 0; }

  // Returns once every member of the job has called it. A member that waits spins briefly, then
  // sleeps until the last one arrives. Everything a member wrote before it is visible to every
  // member after it. Does nothing when the member is alone.
  void barrier() const { barrier_then(nullptr, nullptr); }

  // A barrier at which the last member to arrive runs completion() before it releases the others
  // (the member alone runs it at once): what must be done once between two phases, with no
  // member in either (the step count between two steps).
  template <class Completion>
  void barrier(const Completion& completion) const {
    barrier_then([](const void* erased) { (*static_cast<const Completion*>(erased))(); },
                 &completion);
  }

  void barrier_then(void (*completion)(const void*), const void* argument) const;

  // This member's share of [0, n): contiguous ranges in member order that cover it, cut at
  // multiples of `grain` (so that neighbouring members do not write to one cache line), the same
  // for the same n, grain and member count.
  std::pair<Index, Index> share(Index n, Index grain = 1) const {
    const Index units = (n + grain - 1) / grain;
    const Index begin = units * index_ / count_ * grain;
    const Index end = units * (index_ + 1) / count_ * grain;
    return {std::min(begin, n), std::min(end, n)};
  }

 private:
  const ThreadTeam* team_;  // null when alone
  int index_;
  int count_;
};

// A member that is the whole team: what code run on one thread passes where a member is asked
// for. Its barriers return at once.
inline TeamMember solo_member() {
  return {nullptr, 0, 1};
}

class ThreadTeam {
 public:
  // Starts `threads` − 1 worker threads (none for 1).
  explicit ThreadTeam(int threads);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return size_; }
  // Jobs run on the worker threads (members 1 …) since the team started, summed over them: what
  // shows that a step was shared, not run alone.
  std::uint64_t worker_jobs() const { return worker_jobs_.load(std::memory_order_relaxed); }

  // Runs job(member) on every member of the team, the calling thread as member 0, and returns
  // when all have returned; with `alone`, only on the calling thread (as the solo member). A job
  // must not start another, nor throw.
  template <class Job>
  void run(const Job& job, bool alone = false) {
    if (alone || size_ == 1) {
      job(solo_member());
      return;
    }
    run_erased([](const void* erased,
                  const TeamMember& member) { (*static_cast<const Job*>(erased))(member); },
               &job);
  }

 private:
  friend class TeamMember;
  using Invoke = void (*)(const void* job, const TeamMember& member);

  void run_erased(Invoke invoke, const void* job);
  void work(int index);
  void arrive_at_barrier(void (*completion)(const void*), const void* argument) const;

  int size_;
  std::vector<std::thread> workers_;
  // The job in hand, written by member 0 before it advances `generation_`.
  Invoke invoke_ = nullptr;
  const void* job_ = nullptr;
  bool stopping_ = false;
  // Each on its own cache line: the members poll them while they wait.
  alignas(64) std::atomic<std::uint32_t> generation_{0};  // one more for each job
  alignas(64) std::atomic<int> finished_{0};              // workers done with the job in hand
  alignas(64) mutable std::atomic<int> arrived_{0};       // members at the barrier
  alignas(64) mutable std::atomic<std::uint32_t> barrier_phase_{0};
  alignas(64) std::atomic<std::uint64_t> worker_jobs_{0};
};

// The process's team, started at the first use with thread_count() threads.
ThreadTeam& thread_team();
// The size of the process's team: 1 until set.
int thread_count();
// Restarts the process's team with `threads` threads (at least 1). Not while a job runs.
void set_thread_count(int threads);

}  // namespace dinam
