#include "app/draw_list_from_model.hpp"

#include <algorithm>
#include <cmath>

#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {
namespace {

// 1, 2 or 5 times a power of ten, nearest below `value`: a tile size a person reads easily.
double round_down_nice(double value) {
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  for (const double step : {5.0, 2.0, 1.0}) {
    if (step * decade <= value) {
      return step * decade;
    }
  }
  return decade;
}

}  // namespace

DrawList make_draw_list(const SceneDescription& scene, const Model& model) {
  DrawList list;
  Vec3 lo = model.node_initial_x.front();
  Vec3 hi = lo;
  for (const Vec3& p : model.node_initial_x) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = std::max((hi - lo).norm(), 1e-3);
  const double min_radius = 0.002 * extent;

  std::vector<float> object_radius;
  for (const ModelObject& object : model.objects) {
    const double r = object.render_radius > 0.0 ? object.render_radius
                                                : std::max(object.wire_radius, min_radius);
    object_radius.push_back(static_cast<float>(r));
  }
  list.point_radius.resize(model.node_count());
  list.point_color.resize(model.node_count());
  for (Index i = 0; i < model.node_count(); ++i) {
    const Index object = model.node_object[i];
    list.point_radius[i] = object_radius[object];
    list.point_color[i] = model.objects[object].color;
  }
  list.segment_points = model.bar_nodes;
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index object = model.node_object[model.bar_nodes[2 * b]];
    list.segment_radius.push_back(object_radius[object]);
    list.segment_color.push_back(model.objects[object].color);
  }

  list.ground_visible = scene.ground.visible;
  // The ground's centre is the foot of the model's centre on the plane.
  const Vec3 center = 0.5 * (lo + hi);
  const Vec3& normal = scene.ground.normal;
  list.ground_center = (center - (center - scene.ground.point).dot(normal) * normal).cast<float>();
  list.ground_normal = normal.cast<float>();
  const double view_distance = (scene.camera.look_at - scene.camera.position).norm();
  // Far enough that its edge, where the checker has faded out, lies near the horizon.
  list.ground_half_size = static_cast<float>(std::max(15.0 * extent, 8.0 * view_distance));
  list.ground_tile = static_cast<float>(round_down_nice(extent / 5.0));

  list.camera.position = scene.camera.position.cast<float>();
  list.camera.look_at = scene.camera.look_at.cast<float>();
  list.camera.up = scene.camera.up.cast<float>();
  list.camera.fov_degrees = static_cast<float>(scene.camera.fov_degrees);
  return list;
}

void positions_for_render(const std::vector<Vec3>& x, std::vector<Vec3f>& out) {
  out.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    out[i] = x[i].cast<float>();
  }
}

}  // namespace dinam
