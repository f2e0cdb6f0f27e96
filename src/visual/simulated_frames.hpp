#pragma once
// What the simulation (or a motion cache) hands to the drawing: the positions of the frames held,
// the bounds of the whole motion, the tears, and the instants of blurred frames.
#include <vector>

#include "core/types.hpp"
#include "dynamics/state.hpp"
#include "render/framing.hpp"
#include "visual/torn_drawing.hpp"

namespace dinam {

// Node positions of consecutive frames first_frame, first_frame + 1, … (frame k at
// t = (k − 1)/fps), in single precision, and the bounds of the whole motion they belong to, which
// frame the camera, the ground and the shadows: so frames drawn in chunks are those of one run.
struct SimulatedFrames {
  int first_frame = 1;
  std::vector<std::vector<Vec3f>> positions;  // (frames held) × (n_nodes)
  Bounds motion;                              // every position of every frame of the motion
  Bounds subject;  // every frame's subject box (core/subject_box.hpp): what camera: auto frames
  double seconds = 0.0;        // wall time spent simulating or reading
  SettleOutcome settled;       // how the settling phase ended (simulated only)
  std::vector<TornBar> tears;  // in the order they broke
  // Motion blur: the positions of each frame's instants (frame after frame, instants_per_frame
  // each) and their times; empty when each frame is one instant.
  int instants_per_frame = 1;
  std::vector<std::vector<Vec3f>> instants;  // (frames held × instants_per_frame) × (n_nodes)
  std::vector<double> instant_times;         // s

  int last_frame() const { return first_frame + static_cast<int>(positions.size()) - 1; }
  const std::vector<Vec3f>& at(int frame) const {
    return positions[static_cast<std::size_t>(frame - first_frame)];
  }
};

}  // namespace dinam
