#include "visual/draw_list_from_model.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>
#include <utility>

#include "core/error.hpp"
#include "io/png_file.hpp"
#include "model/model.hpp"
#include "render/osmesa_renderer.hpp"
#include "scene/scene_description.hpp"
#include "visual/sharp_edges.hpp"
#include "visual/surface_subdivision.hpp"

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

// m, the size of the scene the draw list frames: the diameter of every frame's positions.
double drawn_extent(const Bounds& motion) {
  return std::max(static_cast<double>(2.0f * motion.radius()), 1e-3);
}

// Each drawn object's surface triangles (its faces fanned), by object; none for a wire object.
std::vector<Index> surface_triangle_counts(const SceneDescription& scene, const Model& model) {
  std::vector<Index> counts(model.objects.size(), 0);
  for (Index f = 0; f < model.face_count(); ++f) {
    const Index object = model.node_object[model.face_nodes[model.face_offsets[f]]];
    if (scene.objects[static_cast<std::size_t>(object)].style != DrawStyle::kWire) {
      counts[static_cast<std::size_t>(object)] +=
          model.face_offsets[f + 1] - model.face_offsets[f] - 2;
    }
  }
  return counts;
}

// The triangles a surface may be refined to by default. Software OpenGL draws a refined triangle
// for about 5 µs at 720p (bench_render's shipped scenes, as simulated against smooth), so the
// default stays within 1.3× of drawing the mesh as simulated: the paper's flag (450 triangles) at
// level 1, 65.8 → 69.6 ms a frame (at level 2, 96 ms); a finer mesh, which shows no facets, as is.
constexpr Index kMostAutomaticTriangles = 2000;

// The points a subdivided surface's point holds weights of, about, at level 2 (for the memory
// estimate): its 1-ring's ring.
constexpr std::uint64_t kWeightsPerDerivedPoint = 30;

}  // namespace

int subdivision_level(const ObjectDesc& object, Index triangles, bool can_tear) {
  if (object.style == DrawStyle::kWire || triangles == 0 || can_tear ||
      object.shading != Shading::kSmooth) {
    return 0;
  }
  if (object.subdivide) {
    return *object.subdivide;
  }
  int level = 0;
  while (level < 2 && triangles * (Index{4} << (2 * level)) <= kMostAutomaticTriangles) {
    ++level;
  }
  return level;
}

RenderSettings render_settings(const SceneDescription& scene) {
  return {scene.image_width, scene.image_height, scene.quality.samples,
          scene.quality.shadows ? scene.quality.shadow_resolution : 0, scene.quality.look};
}

Bounds motion_bounds(const std::vector<std::vector<Vec3f>>& frames) {
  Bounds bounds;
  for (const auto& positions : frames) {
    for (const Vec3f& p : positions) {
      bounds.add(p);
    }
  }
  return bounds;
}

Bounds drawn_bounds(const Bounds& motion, const Bounds& subject) {
  if (subject.empty()) {
    return motion;
  }
  const Vec3f room = Vec3f::Constant(subject.radius());
  Bounds bounds;
  bounds.min = motion.min.cwiseMax(subject.min - room);
  bounds.max = motion.max.cwiseMin(subject.max + room);
  return bounds;
}

std::vector<Image> read_textures(const SceneDescription& scene) {
  std::vector<Image> textures(scene.objects.size());
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const ObjectDesc& desc = scene.objects[o];
    if (desc.style == DrawStyle::kWire || desc.texture.empty()) {
      continue;
    }
    try {
      textures[o] = read_png(desc.texture);
    } catch (const std::exception& e) {
      throw_user_error(desc.texture_loc,
                       "texture file '{}' cannot be read as a PNG ({}); save it again as a PNG",
                       desc.texture.string(), e.what());
    }
  }
  return textures;
}

std::vector<float> drawn_wire_radii(const Model& model, const Bounds& motion) {
  const double min_radius = 0.002 * drawn_extent(motion);
  // The wire's radius, but at least 0.2 % of the scene's size so that a fine wire shows; yet not
  // so much that the bars of a dense mesh (a million-bar lattice) merge into a solid sheet, so at
  // most a quarter of its median bar.
  std::vector<float> radii;
  std::vector<double> lengths;
  for (const ModelObject& object : model.objects) {
    const auto first = model.bar_rest_length.begin() + object.first_bar;
    lengths.assign(first, first + object.bar_count);
    std::nth_element(lengths.begin(), lengths.begin() + object.bar_count / 2, lengths.end());
    const double visible = std::min(min_radius, 0.25 * lengths[object.bar_count / 2]);
    const double r =
        object.render_radius > 0.0 ? object.render_radius : std::max(object.wire_radius, visible);
    radii.push_back(static_cast<float>(r));
  }
  return radii;
}

DrawList make_draw_list(const SceneDescription& scene, const Model& model, const Bounds& motion) {
  return make_draw_list(scene, model, motion, read_textures(scene));
}

DrawList make_draw_list(const SceneDescription& scene, const Model& model, const Bounds& motion,
                        std::vector<Image> textures) {
  DrawList list;
  const double extent = drawn_extent(motion);
  const std::vector<float> object_radius = drawn_wire_radii(model, motion);
  std::vector<bool> object_wire;
  for (const ObjectDesc& desc : scene.objects) {
    object_wire.push_back(desc.style != DrawStyle::kSurface);
  }
  list.point_radius.resize(model.node_count());
  list.point_color.resize(model.node_count());
  list.point_finish.resize(model.node_count());
  list.point_uv = model.node_uv;
  // No spheres at the nodes: the bars' capsules join there with their round ends (flat ends for
  // an object drawn without joints).
  for (Index i = 0; i < model.node_count(); ++i) {
    const Index object = model.node_object[i];
    list.point_radius[i] = 0.0f;
    list.point_color[i] = model.objects[object].color;
    list.point_finish[i] = scene.objects[static_cast<std::size_t>(object)].finish;
  }
  for (Index b = 0; b < model.bar_count(); ++b) {
    // A surface object still shows its loose bars (a flag's ropes): they are on no face.
    const Index object = model.node_object[model.bar_nodes[2 * b]];
    if (!object_wire[object] && model.bar_on_face[b] != 0) {
      continue;
    }
    list.segment_points.push_back(model.bar_nodes[2 * b]);
    list.segment_points.push_back(model.bar_nodes[2 * b + 1]);
    const bool round = scene.objects[static_cast<std::size_t>(object)].joints;
    list.segment_radius.push_back(round ? object_radius[object] : -object_radius[object]);
    list.segment_color.push_back(model.objects[object].color);
    list.segment_finish.push_back(scene.objects[static_cast<std::size_t>(object)].finish);
  }

  // Surfaces: one batch per drawn object, its faces fanned into triangles.
  std::vector<int> batch_of_object(model.objects.size(), -1);
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ObjectDesc& desc = scene.objects[o];
    if (desc.style == DrawStyle::kWire) {
      continue;
    }
    SurfaceBatch batch;
    if (!desc.texture.empty()) {
      list.textures.push_back(std::move(textures[o]));
      batch.texture = static_cast<int>(list.textures.size()) - 1;
    }
    batch_of_object[o] = static_cast<int>(list.surfaces.size());
    list.surfaces.push_back(std::move(batch));
  }
  std::vector<std::vector<Index>> triangle_face(list.surfaces.size());  // each batch's
  for (Index f = 0; f < model.face_count(); ++f) {
    const Index begin = model.face_offsets[f];
    const Index end = model.face_offsets[f + 1];
    const int batch = batch_of_object[model.node_object[model.face_nodes[begin]]];
    if (batch < 0) {
      continue;
    }
    auto& triangles = list.surfaces[static_cast<std::size_t>(batch)].triangles;
    for (Index k = begin + 1; k + 1 < end; ++k) {
      triangles.insert(triangles.end(),
                       {model.face_nodes[begin], model.face_nodes[k], model.face_nodes[k + 1]});
      triangle_face[static_cast<std::size_t>(batch)].push_back(f);
    }
  }

  // Surfaces drawn smooth: each object's triangles subdivided to its level, over points made from
  // its nodes; the nodes' own positions, the bars' capsules and the motion are left as they are.
  const std::vector<Index> triangle_counts = surface_triangle_counts(scene, model);
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const int level =
        batch_of_object[o] < 0
            ? 0
            : subdivision_level(scene.objects[o], triangle_counts[o], model.can_tear());
    if (level == 0) {
      continue;
    }
    SurfaceBatch& batch = list.surfaces[static_cast<std::size_t>(batch_of_object[o])];
    const SubdividedSurface smooth = subdivide_loop(batch.triangles, level, model.node_initial_x);
    const Index first = model.node_count() + list.derived.size();
    batch.triangles = smooth.triangles;
    for (Index& id : batch.triangles) {
      id += first;
    }
    DerivedPoints& derived = list.derived;
    const bool uv = !list.point_uv.empty();
    for (Index k = 0; k < smooth.points.size(); ++k) {
      Vec3f color = Vec3f::Zero();
      Eigen::Vector2f texture_point = Eigen::Vector2f::Zero();
      for (Index j = smooth.points.offsets[k]; j < smooth.points.offsets[k + 1]; ++j) {
        const Index source = smooth.points.sources[j];
        const float weight = smooth.points.weights[j];
        derived.sources.push_back(source);
        derived.weights.push_back(weight);
        color += weight * list.point_color[source];
        if (uv) {
          texture_point += weight * list.point_uv[source];
        }
      }
      derived.offsets.push_back(static_cast<Index>(derived.sources.size()));
      list.point_radius.push_back(0.0f);
      list.point_color.push_back(color);
      list.point_finish.push_back(scene.objects[o].finish);
      if (uv) {
        list.point_uv.push_back(texture_point);
      }
    }
  }

  // Surfaces shaded flat or with sharp edges: drawn as modelled, their points split where faces
  // should not blend (visual/sharp_edges.hpp).
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ObjectDesc& desc = scene.objects[o];
    if (batch_of_object[o] < 0 || desc.shading == Shading::kSmooth) {
      continue;
    }
    const auto b = static_cast<std::size_t>(batch_of_object[o]);
    const double sharp =
        desc.shading == Shading::kFlat ? -1.0 : desc.sharp_angle * std::numbers::pi / 180.0;
    const Index first = model.node_count() + list.derived.size();
    const std::vector<Index> sources = split_at_sharp_edges(
        list.surfaces[b].triangles, triangle_face[b], model.node_initial_x, sharp, first);
    for (const Index source : sources) {
      list.derived.sources.push_back(source);
      list.derived.weights.push_back(1.0f);
      list.derived.offsets.push_back(static_cast<Index>(list.derived.sources.size()));
      list.point_radius.push_back(0.0f);
      list.point_color.push_back(list.point_color[source]);
      list.point_finish.push_back(list.point_finish[source]);
      if (!list.point_uv.empty()) {
        list.point_uv.push_back(list.point_uv[source]);
      }
    }
  }

  // The ground's centre is the foot of the motion's centre on the plane; it reaches far enough
  // that its faded edge lies near the horizon.
  const Vec3 center = motion.center().cast<double>();
  const Vec3& normal = scene.ground.normal;
  list.ground_visible = scene.ground.visible;
  list.ground_checker = scene.ground.checker;
  list.ground_center = (center - (center - scene.ground.point).dot(normal) * normal).cast<float>();
  list.ground_normal = normal.cast<float>();
  list.ground_half_size = static_cast<float>(std::max(30.0 * extent, 50.0));
  list.ground_tile = static_cast<float>(scene.ground.tile.value_or(round_down_nice(extent / 5.0)));
  list.ground_color = scene.ground.color;
  list.ground_checker_color = scene.ground.checker_color;
  list.sky_horizon = scene.sky.horizon;
  list.sky_zenith = scene.sky.zenith;

  list.light_direction = scene.light_direction.cast<float>();
  list.light_size_degrees = static_cast<float>(scene.light_size_degrees);
  list.shadows = scene.quality.shadows;
  // Occlusion reaches a few percent of the subject, and past the thickest wire: far enough for a
  // wire lying on the ground to darken it beside itself, near enough that open space stays lit.
  const float thickest =
      object_radius.empty() ? 0.0f : *std::max_element(object_radius.begin(), object_radius.end());
  list.occlusion_radius = std::max(static_cast<float>(0.03 * extent), 3.0f * thickest);
  // The shadow map must hold the casters and where their shadows land: the motion's box and its
  // projection along the light onto the ground.
  Bounds shadow = motion;
  const Vec3 light = scene.light_direction.normalized();
  const double light_height = light.dot(normal);
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) != 0 ? motion.max.x() : motion.min.x(),
                 (corner & 2) != 0 ? motion.max.y() : motion.min.y(),
                 (corner & 4) != 0 ? motion.max.z() : motion.min.z());
    if (light_height > 0.05) {  // a light near the horizon casts endless shadows: leave them out
      const double height = (p - scene.ground.point).dot(normal);
      shadow.add((p - (height / light_height) * light).cast<float>());
    }
  }
  list.shadow_bounds_min = shadow.min;
  list.shadow_bounds_max = shadow.max;
  return list;
}

void positions_for_render(const std::vector<Vec3>& x, std::vector<Vec3f>& out) {
  out.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    out[i] = x[i].cast<float>();
  }
}

std::uint64_t draw_list_bytes(const SceneDescription& scene, const Model& model) {
  const auto nodes = static_cast<std::uint64_t>(model.node_count());
  const auto bars = static_cast<std::uint64_t>(model.bar_count());
  const auto face_nodes = static_cast<std::uint64_t>(model.face_nodes.size());
  const std::uint64_t per_bar = 2 * sizeof(Index) + sizeof(float) + sizeof(Vec3f) +
                                2 * 10 * sizeof(float);  // 10 floats an instance, twice
  const std::uint64_t per_node = sizeof(float) + sizeof(Vec3f) + sizeof(Eigen::Vector2f) +
                                 2 * (6 + 5) * sizeof(float);  // vertices and attributes, twice
  // A face of k nodes is k − 2 triangles of three ids, held by the list and by Mesa.
  std::uint64_t bytes = bars * per_bar + nodes * per_node + face_nodes * 2 * 3 * sizeof(Index);
  // A subdivided surface: 4^level triangles each, about half as many points, each with its
  // weights and the per-point arrays.
  const std::vector<Index> triangle_counts = surface_triangle_counts(scene, model);
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const int level = subdivision_level(scene.objects[o], triangle_counts[o], model.can_tear());
    if (level > 0) {
      const auto triangles = static_cast<std::uint64_t>(triangle_counts[o]) << (2 * level);
      const std::uint64_t points = triangles / 2;
      bytes += triangles * 2 * 3 * sizeof(Index) +
               points * (per_node + kWeightsPerDerivedPoint * (sizeof(Index) + sizeof(float)));
    }
  }
  return bytes;
}

}  // namespace dinam
