#pragma once
// The cyclorama's size: a studio's seamless backdrop, the floor curving up into a wall all round
// the scene. Every camera of the run stands inside it, so that wherever the camera goes (an
// orbit, a path through keys) it sees the wall behind the subject and never its edge, and the
// wall rises high enough to fill every view above the horizon.
#include <vector>

#include "render/draw_list.hpp"
#include "render/framing.hpp"

namespace dinam {

struct FrameCameras;
struct SceneDescription;

// Sets list.backdrop_radius, _curve and _height around list.ground_center for `cameras`: the
// radius at least the subject's size across the ground (its box's diagonal, so the subject has
// room in front of the wall) and a quarter farther out than the farthest camera; the curve a
// third of the radius; the wall as high as the steepest view's upper edge climbs at the far side.
void fit_backdrop(const Bounds& subject, const std::vector<RenderCamera>& cameras, DrawList& list);

// The same for a run's frames and instants, when the scene asks for a cyclorama (else nothing).
void fit_backdrop(const SceneDescription& scene, const Bounds& subject, const FrameCameras& cameras,
                  DrawList& list);

}  // namespace dinam
