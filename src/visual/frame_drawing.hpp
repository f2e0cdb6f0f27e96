#pragma once
// Drawing the frames held: each frame's positions (or the mean of its motion-blur instants) seen
// from its camera, the bars torn by then left out, through any Renderer (OSMesa, or a recording
// one in tests).
#include <functional>

#include "core/image.hpp"
#include "render/draw_list.hpp"
#include "render/renderer.hpp"
#include "visual/frame_cameras.hpp"
#include "visual/simulated_frames.hpp"

namespace dinam {

// Draws frames first … last (all held), handing each picture to `on_image(frame, image)`;
// `cameras` are those of frame_cameras. A frame with instants is their mean (motion blur).
void draw_frames(Renderer& renderer, const DrawList& list, const SimulatedFrames& frames,
                 const FrameCameras& cameras, int first, int last,
                 const std::function<void(int, const Image&)>& on_image);

}  // namespace dinam
