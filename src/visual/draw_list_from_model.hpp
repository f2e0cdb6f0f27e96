#pragma once
// The bridge from the physical model to what the renderer draws (the visual stage, between the
// model and the renderer: the one place that knows both sides).
#include <cstdint>
#include <vector>

#include "render/draw_list.hpp"
#include "render/framing.hpp"

namespace dinam {

struct Model;
struct RenderSettings;
struct SceneDescription;
struct ObjectDesc;

// Bars become segments and nodes become joints, each object in its colour; the faces of objects
// drawn as surfaces become triangle batches (textured when the scene names a texture). A bar is
// drawn with the object's render_radius, else its wire radius, but never thinner than 0.2 % of
// the model's size, so a cloth of fine threads stays visible. `motion` bounds every frame's
// positions: the ground and the shadow map are framed on it.
DrawList make_draw_list(const SceneDescription& scene, const Model& model, const Bounds& motion);

// The radius each object's bars are drawn with (m), as make_draw_list draws them.
std::vector<float> drawn_wire_radii(const Model& model, const Bounds& motion);

// The same, with the textures already read by read_textures.
DrawList make_draw_list(const SceneDescription& scene, const Model& model, const Bounds& motion,
                        std::vector<Image> textures);

// Every texture the scene draws, decoded, one per object (empty for an object without one).
// The render reads them before it simulates, so a damaged PNG is a scene error at its key (a
// UserError), found in a second rather than after the simulation.
std::vector<Image> read_textures(const SceneDescription& scene);

// The renderer's settings from the scene: image size, multisampling, shadow map.
RenderSettings render_settings(const SceneDescription& scene);

// The bounds of every position of every frame.
Bounds motion_bounds(const std::vector<std::vector<Vec3f>>& frames);

// The bounds the draw list is sized on (wire radii, the ground's tiles, the shadow map): the
// motion's, but no farther than half the subject's diameter beyond the subject's box (its
// percentile box, core/subject_box.hpp). A node torn loose and flung a hundred metres, drawn by
// nothing, then does not thicken every wire, coarsen the floor and blur the shadows.
Bounds drawn_bounds(const Bounds& motion, const Bounds& subject);

// Bytes of the draw list's arrays for `model` and of the renderer's per-frame copies of them (in
// dinam and in Mesa's buffer objects), with the subdivided surfaces, for the memory estimate.
std::uint64_t draw_list_bytes(const SceneDescription& scene, const Model& model);

// How many levels of Loop subdivision an object's surface of `triangles` is drawn with: its
// `subdivide`, else 2 where that makes at most 2 000 triangles (1 where one level does, else 0);
// none for a wire, and none in a scene whose bars can tear (a tear hides the coarse triangles on
// its bar, which a smooth surface no longer has).
int subdivision_level(const ObjectDesc& object, Index triangles, bool can_tear);

// Node positions in single precision, for the renderer.
void positions_for_render(const std::vector<Vec3>& x, std::vector<Vec3f>& out);

}  // namespace dinam
