#include "visual/frame_cameras.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/model.hpp"
#include "render/camera_path.hpp"
#include "render/framing.hpp"
#include "scene/scene_description.hpp"
#include "visual/simulated_frames.hpp"

namespace dinam {
namespace {

// The scene's camera as a function of time and of the points' positions then.
class CameraRig {
 public:
  CameraRig(const SceneDescription& scene, const Model& model, const SimulatedFrames& frames)
      : desc_(scene.camera),
        up_(desc_.up.cast<float>()),
        fov_(static_cast<float>(desc_.fov_degrees)),
        duration_(scene.duration) {
    const float aspect =
        static_cast<float>(scene.image_width) / static_cast<float>(scene.image_height);
    switch (desc_.mode) {
      case CameraDesc::Mode::kFixed:
        still_ = {desc_.position.cast<float>(), desc_.look_at.cast<float>(), up_, fov_};
        break;
      case CameraDesc::Mode::kAuto:
        still_ = frame_box(frames.subject, desc_.direction.cast<float>(), up_, fov_, aspect);
        break;
      case CameraDesc::Mode::kFollow:
        for (const ModelObject& object : model.objects) {
          if (object.name == desc_.follow) {
            for (Index i = 0; i < object.node_count; ++i) {
              followed_.push_back(object.first_node + i);
            }
          }
        }
        break;
      case CameraDesc::Mode::kPath:
        for (const CameraKeyDesc& key : desc_.keys) {
          keys_.push_back({key.time, key.position.cast<float>(), key.look_at.cast<float>(),
                           static_cast<float>(key.fov_degrees)});
        }
        break;
      case CameraDesc::Mode::kOrbit:
        set_up_orbit(frames.subject, aspect);
        break;
    }
  }

  RenderCamera at(double t, const std::vector<Vec3f>& positions) const {
    switch (desc_.mode) {
      case CameraDesc::Mode::kFixed:
      case CameraDesc::Mode::kAuto:
        return still_;
      case CameraDesc::Mode::kFollow:
        return follow_points(positions, followed_, desc_.offset.cast<float>(), up_, fov_);
      case CameraDesc::Mode::kPath:
        return camera_on_path(keys_, t, up_);
      case CameraDesc::Mode::kOrbit: {
        const double turns = desc_.orbit.turns * std::clamp(t / duration_, 0.0, 1.0);
        const double angle = (desc_.orbit.start_degrees / 360.0 + turns) * 2.0 * std::numbers::pi;
        return orbit_camera(orbit_center_, orbit_radius_, orbit_height_, static_cast<float>(angle),
                            up_, fov_);
      }
    }
    return still_;
  }

 private:
  // Unless given, the centre is the subject's, and the eye stands where the subject's bounding
  // sphere fills the narrower field of view (with 8 % room), a fifth of the radius above it.
  void set_up_orbit(const Bounds& subject, float aspect) {
    const OrbitDesc& orbit = desc_.orbit;
    orbit_center_ = orbit.center ? orbit.center->cast<float>() : subject.center();
    const float half_fov = 0.5f * fov_ * std::numbers::pi_v<float> / 180.0f;
    const float narrow = std::min(half_fov, std::atan(aspect * std::tan(half_fov)));
    const float sphere = subject.empty() ? 1.0f : std::max(subject.radius(), 1e-3f);
    const float distance = 1.08f * sphere / std::sin(narrow);
    if (orbit.radius) {
      orbit_radius_ = static_cast<float>(*orbit.radius);
      orbit_height_ = orbit.height_given ? static_cast<float>(orbit.height) : 0.2f * orbit_radius_;
    } else if (orbit.height_given) {
      orbit_height_ = static_cast<float>(orbit.height);
      orbit_radius_ = std::sqrt(std::max(distance * distance - orbit_height_ * orbit_height_,
                                         0.01f * distance * distance));
    } else {
      orbit_radius_ = distance / std::sqrt(1.04f);
      orbit_height_ = 0.2f * orbit_radius_;
    }
  }

  const CameraDesc& desc_;
  Vec3f up_;
  float fov_;
  double duration_;
  RenderCamera still_;
  std::vector<Index> followed_;
  std::vector<CameraKey> keys_;
  Vec3f orbit_center_ = Vec3f::Zero();
  float orbit_radius_ = 1.0f;
  float orbit_height_ = 0.0f;
};

}  // namespace

FrameCameras frame_cameras(const SceneDescription& scene, const Model& model,
                           const SimulatedFrames& frames) {
  const CameraRig rig(scene, model, frames);
  FrameCameras cameras;
  cameras.frames.reserve(frames.positions.size());
  for (std::size_t f = 0; f < frames.positions.size(); ++f) {
    const double t = static_cast<double>(frames.first_frame - 1 + static_cast<int>(f)) / scene.fps;
    cameras.frames.push_back(rig.at(t, frames.positions[f]));
  }
  cameras.instants.reserve(frames.instants.size());
  for (std::size_t i = 0; i < frames.instants.size(); ++i) {
    cameras.instants.push_back(rig.at(frames.instant_times[i], frames.instants[i]));
  }
  return cameras;
}

}  // namespace dinam
