#include "run/frame_source.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>

#include "cache/motion_cache.hpp"
#include "core/stop_request.hpp"
#include "core/subject_box.hpp"
#include "core/thread_governor.hpp"
#include "core/wall_clock.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "stepping/stepper_kind.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {

std::vector<int> shutter_offsets(const MotionBlurDesc& blur, int steps_per_frame) {
  std::vector<int> offsets;
  if (!blur.enabled()) {
    return offsets;
  }
  const double open = blur.shutter * static_cast<double>(steps_per_frame);  // steps
  for (int k = 0; k < blur.samples; ++k) {
    const double fraction = (static_cast<double>(k) + 0.5) / blur.samples - 0.5;
    offsets.push_back(static_cast<int>(std::lround(fraction * open)));
  }
  return offsets;
}

// Steps taken between two checks for SIGINT or SIGTERM: 256, fewer on a large model, so that a
// run of them stays near 10⁷ springs and nodes stepped (a few tens of milliseconds) and a signal
// is honoured well within a second. (The implicit integrator also checks within its steps.)
std::int64_t steps_between_stop_checks(const Model& model) {
  constexpr double kItemsBetweenChecks = 1e7;
  const double items =
      static_cast<double>(model.node_count() + model.bar_count() + model.bend_count());
  return std::clamp<std::int64_t>(std::llround(kItemsBetweenChecks / std::max(items, 1.0)), 1, 256);
}

void run_dynamics(const Model& model, const TimeStep& timestep, int last, bool track_energy,
                  const std::function<void(int, const State&)>& on_frame,
                  const std::vector<int>& shutter,
                  const std::function<void(int, int, const State&)>& on_instant) {
  // The steps at which frames and instants are taken, in order: offsets ascend, and one frame's
  // last instant (at most half a frame after it) precedes the next frame's first.
  const auto frame_step = [&](int frame) {
    return static_cast<std::int64_t>(frame - 1) * timestep.steps_per_frame;
  };
  const auto instant_step = [&](std::size_t i) {
    const auto frame = static_cast<int>(i / shutter.size()) + 1;
    return std::max<std::int64_t>(frame_step(frame) + shutter[i % shutter.size()], 0);
  };
  const std::size_t instants = shutter.size() * static_cast<std::size_t>(last);
  std::int64_t final_step = frame_step(last);
  if (instants > 0) {
    final_step = std::max(final_step, instant_step(instants - 1));
  }
  const std::unique_ptr<Stepper> stepper = stepper_kind(model).make_stepper(model, timestep);
  State state = stepper->start(track_energy);
  const std::int64_t steps_between_checks = steps_between_stop_checks(model);
  // The thread count follows the machine between runs of steps (core/thread_governor.hpp).
  ThreadGovernor governor;
  int frame = 1;
  std::size_t instant = 0;
  for (std::int64_t n = 0;;) {
    for (; instant < instants && instant_step(instant) == n; ++instant) {
      on_instant(static_cast<int>(instant / shutter.size()) + 1,
                 static_cast<int>(instant % shutter.size()), state);
    }
    if (frame <= last && frame_step(frame) == n) {
      on_frame(frame++, state);
    }
    if (n == final_step) {
      break;
    }
    // On to the next frame or instant, in runs of steps that the thread team takes in one go
    // (dynamics/integrator.hpp), short enough to stop soon after SIGINT or SIGTERM however long
    // a frame takes.
    std::int64_t next = std::min(final_step, n + steps_between_checks);
    if (instant < instants) {
      next = std::min(next, instant_step(instant));
    }
    if (frame <= last) {
      next = std::min(next, frame_step(frame));
    }
    stop_if_asked();
    governor.before_run();
    stepper->advance(state, next - n);
    governor.after_run(next - n);
    n = next;
  }
}

SimulatedFrames simulate_frames(const Model& model, const TimeStep& timestep, int last,
                                bool track_energy,
                                const std::function<void(int, const State&)>& on_frame,
                                const MotionBlurDesc* blur) {
  const auto start = Clock::now();
  SimulatedFrames frames;
  frames.positions.resize(static_cast<std::size_t>(last));
  const std::vector<int> shutter =
      blur != nullptr ? shutter_offsets(*blur, timestep.steps_per_frame) : std::vector<int>{};
  if (!shutter.empty()) {
    frames.instants_per_frame = static_cast<int>(shutter.size());
    frames.instants.resize(shutter.size() * static_cast<std::size_t>(last));
    frames.instant_times.resize(frames.instants.size());
  }
  run_dynamics(
      model, timestep, last, track_energy,
      [&](int frame, const State& state) {
        positions_for_render(state.x, frames.positions[static_cast<std::size_t>(frame - 1)]);
        if (frame == 1) {
          frames.settled = state.settled;
        }
        record_tears(model, state, frame, frames.tears);
        if (on_frame) {
          on_frame(frame, state);
        }
      },
      shutter,
      [&](int frame, int k, const State& state) {
        const std::size_t i =
            static_cast<std::size_t>(frame - 1) * shutter.size() + static_cast<std::size_t>(k);
        positions_for_render(state.x, frames.instants[i]);
        // The instant's own time: the frame's, moved by its offset in steps (an instant before
        // t = 0 shows the start, but keeps its time for a moving camera).
        frames.instant_times[i] =
            static_cast<double>(static_cast<std::int64_t>(frame - 1) * timestep.steps_per_frame +
                                shutter[static_cast<std::size_t>(k)]) *
            timestep.dt;
      });
  frames.motion = motion_bounds(frames.positions);
  for (const std::vector<Vec3f>& positions : frames.positions) {
    Vec3f lo;
    Vec3f hi;
    subject_box(positions, lo, hi);
    frames.subject.add(lo);
    frames.subject.add(hi);
  }
  frames.seconds = seconds_since(start);
  return frames;
}

std::string settle_summary(const SettleOutcome& settled, double motion_dt) {
  if (!settled.ran) {
    return "";
  }
  const double dt = settled.step > 0.0 ? settled.step : motion_dt;
  if (settled.by_newton) {
    const std::string creep =
        settled.steps == 0
            ? ""
            : fmt::format(", after {} steps ({:g} s) of relaxation through a buckling",
                          settled.steps, static_cast<double>(settled.steps) * dt);
    return fmt::format(
        "settled under gravity by Newton's method in {} iterations{}; the largest "
        "out-of-balance force is {:.2g} of a node's weight",
        settled.newton_iterations, creep, settled.residual);
  }
  const std::string instead =
      settled.fallback.empty() ? ""
                               : fmt::format(" (instead of Newton's method: {})", settled.fallback);
  return fmt::format(
      "settled under gravity by relaxation in {:g} s ({} steps: {} overdamped, then {} of kinetic "
      "damping with {} restarts from rest){}; the largest out-of-balance force is {:.2g} of a "
      "node's weight",
      static_cast<double>(settled.steps) * dt, settled.steps, settled.viscous_steps,
      settled.steps - settled.viscous_steps, settled.restarts, instead, settled.residual);
}

SimulatedFrames cached_frames(const MotionCache& cache, int first, int last,
                              const MotionBlurDesc* blur) {
  const auto start = Clock::now();
  SimulatedFrames frames;
  frames.first_frame = first;
  frames.positions = cache.read_frames(first, last);
  const CacheManifest& manifest = cache.manifest();
  if (blur != nullptr && blur->enabled()) {
    const CacheInstants& cached = manifest.instants;
    frames.instants_per_frame = cached.per_frame;
    frames.instants = cache.read_instants(first, last);
    for (int frame = first; frame <= last; ++frame) {
      for (const int offset : cached.offsets) {
        frames.instant_times.push_back(
            static_cast<double>(static_cast<std::int64_t>(frame - 1) * manifest.steps_per_frame +
                                offset) *
            manifest.timestep);
      }
    }
  }
  for (const CacheTear& tear : manifest.tears) {
    frames.tears.push_back({tear.frame, tear.n0, tear.n1});
  }
  for (const FrameBounds& bounds : manifest.frame_bounds) {
    frames.motion.add(bounds.min);
    frames.motion.add(bounds.max);
    frames.subject.add(bounds.subject_min);
    frames.subject.add(bounds.subject_max);
  }
  frames.seconds = seconds_since(start);
  return frames;
}

}  // namespace dinam
