#include "visual/frame_drawing.hpp"

#include <vector>

#include "core/error.hpp"
#include "visual/torn_drawing.hpp"

namespace dinam {

void draw_frames(Renderer& renderer, const DrawList& list, const SimulatedFrames& frames,
                 const FrameCameras& cameras, int first, int last,
                 const std::function<void(int, const Image&)>& on_image) {
  DINAM_CHECK(first >= frames.first_frame && last <= frames.last_frame());
  Image image;
  // With tears, a copy of the list loses each torn bar from the first frame that shows it broken.
  DrawList torn;
  if (!frames.tears.empty()) {
    torn = list;
  }
  std::size_t shown = 0;
  std::vector<FrameSample> samples;
  for (int frame = first; frame <= last; ++frame) {
    const std::size_t before = shown;
    while (shown < frames.tears.size() && frames.tears[shown].frame <= frame) {
      hide_torn_bar(frames.tears[shown++], torn);
    }
    if (shown > before) {
      torn.revision = new_draw_list_revision();
    }
    const auto held = static_cast<std::size_t>(frame - frames.first_frame);
    samples.clear();
    if (frames.instants.empty()) {
      samples.push_back({&frames.at(frame), cameras.frames[held]});
    } else {
      const auto n = static_cast<std::size_t>(frames.instants_per_frame);
      for (std::size_t i = held * n; i < (held + 1) * n; ++i) {
        samples.push_back({&frames.instants[i], cameras.instants[i]});
      }
    }
    renderer.render(frames.tears.empty() ? list : torn, samples, image);
    on_image(frame, image);
  }
}

}  // namespace dinam
