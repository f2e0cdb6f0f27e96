#include "visual/backdrop.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/scene_description.hpp"
#include "visual/frame_cameras.hpp"

namespace dinam {

void fit_backdrop(const Bounds& subject, const std::vector<RenderCamera>& cameras, DrawList& list) {
  const Vec3f normal = list.ground_normal.normalized();
  const Vec3f diagonal = subject.empty() ? Vec3f::Zero() : Vec3f(subject.max - subject.min);
  float radius = (diagonal - diagonal.dot(normal) * normal).norm();
  for (const RenderCamera& camera : cameras) {
    const Vec3f offset = camera.position - list.ground_center;
    radius = std::max(radius, 1.25f * (offset - offset.dot(normal) * normal).norm());
  }
  radius = std::max(radius, 1e-3f);
  // The wall's top must stay above the picture's upper edge where that edge meets the wall: at
  // most the bowl's diameter from the eye, climbing at the view's pitch plus half its field
  // (capped at 75°: a camera looking nearly straight up sees the sky through any wall).
  constexpr float kDegree = std::numbers::pi_v<float> / 180.0f;
  float height = radius;
  for (const RenderCamera& camera : cameras) {
    const Vec3f sight = (camera.look_at - camera.position).normalized();
    const float pitch = std::asin(std::clamp(sight.dot(normal), -1.0f, 1.0f));
    const float top = std::min(pitch + 0.5f * camera.fov_degrees * kDegree, 75.0f * kDegree);
    const float eye_height = (camera.position - list.ground_center).dot(normal);
    height = std::max(height, 1.1f * (eye_height + 2.0f * radius * std::tan(top)));
  }
  list.backdrop_radius = radius;
  list.backdrop_curve = radius / 3.0f;
  list.backdrop_height = height;
}

void fit_backdrop(const SceneDescription& scene, const Bounds& subject, const FrameCameras& cameras,
                  DrawList& list) {
  if (!scene.ground.cyclorama || !scene.ground.visible) {
    return;
  }
  std::vector<RenderCamera> all = cameras.frames;
  all.insert(all.end(), cameras.instants.begin(), cameras.instants.end());
  fit_backdrop(subject, all, list);
}

}  // namespace dinam
