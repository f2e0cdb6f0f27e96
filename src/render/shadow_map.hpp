#pragma once
// The sun's shadow map: depth seen along the light over a box that holds every shadow caster,
// read back with hardware depth comparison (filtered edges) and as plain depths (the soft
// shadows' search for occluders).
#include "render/camera.hpp"
#include "render/draw_list.hpp"

namespace dinam {

class ShadowMap {
 public:
  explicit ShadowMap(int resolution);  // texels per side
  ~ShadowMap();
  ShadowMap(const ShadowMap&) = delete;
  ShadowMap& operator=(const ShadowMap&) = delete;

  // Binds the map as the target of a depth-only pass framed on the list's shadow bounds, seen
  // along `light_direction` (unit, towards the light), and returns that pass's clip_from_world.
  // `light_from_world` receives the lookup matrix, to the map's [0, 1]³.
  Mat4f begin(const DrawList& list, const Vec3f& light_direction, Mat4f& light_from_world);
  void end();

  // Binds the map on two texture units: compared (sampler2DShadow) and raw (sampler2D).
  void bind(int compare_unit, int depth_unit) const;
  // Leaves those units empty.
  static void unbind(int compare_unit, int depth_unit);

 private:
  int resolution_;
  unsigned framebuffer_ = 0;
  unsigned texture_ = 0;
  unsigned compare_sampler_ = 0;
  unsigned depth_sampler_ = 0;
};

}  // namespace dinam
