#include "model/tie_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/closest_points.hpp"
#include "core/error.hpp"
#include "model/frequency_bound.hpp"
#include "model/model.hpp"

namespace dinam {

namespace {

// The point of a target nearest a node: its nodes, their weights, and its distance.
struct NearestPoint {
  std::array<Index, 3> nodes{-1, -1, -1};
  std::array<double, 3> weights{0.0, 0.0, 0.0};
  Vec3 position = Vec3::Zero();
  double distance = std::numeric_limits<double>::infinity();
};

// The point of segment ab nearest p, as the weight of b.
double nearest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length_squared = ab.squaredNorm();
  return length_squared > 0.0 ? std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
}

void keep_if_nearer(const Model& model, const Vec3& p, const std::array<Index, 3>& nodes,
                    const std::array<double, 3>& weights, NearestPoint& best) {
  Vec3 point = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    point += weights[k] * model.node_initial_x[nodes[k]];
  }
  const double distance = (p - point).norm();
  if (distance < best.distance) {
    best = {nodes, weights, point, distance};
  }
}

// The target's point nearest p over its bars and its faces (each fanned into triangles).
NearestPoint nearest_point(const Model& model, Index target, const Vec3& p) {
  const ModelObject& object = model.objects[target];
  NearestPoint best;
  for (Index b = object.first_bar; b < object.first_bar + object.bar_count; ++b) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    const double s = nearest_on_segment(p, model.node_initial_x[n0], model.node_initial_x[n1]);
    keep_if_nearer(model, p, {n0, n1, n1}, {1.0 - s, s, 0.0}, best);
  }
  for (Index f = 0; f < model.face_count(); ++f) {
    const Index begin = model.face_offsets[f];
    const Index end = model.face_offsets[f + 1];
    if (model.node_object[model.face_nodes[begin]] != target) {
      continue;
    }
    for (Index k = begin + 1; k + 1 < end; ++k) {
      const std::array<Index, 3> corners{model.face_nodes[begin], model.face_nodes[k],
                                         model.face_nodes[k + 1]};
      keep_if_nearer(model, p, corners,
                     closest_point_of_triangle(p, model.node_initial_x[corners[0]],
                                               model.node_initial_x[corners[1]],
                                               model.node_initial_x[corners[2]]),
                     best);
    }
  }
  return best;
}

Index object_named(const SceneDescription& scene, const AttachmentDesc& attachment) {
  std::string names;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    if (scene.objects[o].name == attachment.target) {
      return static_cast<Index>(o);
    }
    names += (names.empty() ? "'" : ", '") + scene.objects[o].name + "'";
  }
  throw_user_error(attachment.target_loc,
                   "'to: {}' names no object of the scene (its objects: {}); the target is "
                   "another object's 'name'",
                   attachment.target, names);
}

// A rigid tie's stiffness: its oscillation, with its node's mass and its point's, at
// kRigidTieFrequency of the structure's highest frequency bound.
void stiffen_rigid_ties(Model& model) {
  Ties& ties = model.ties;
  if (std::none_of(ties.rigid.begin(), ties.rigid.end(), [](std::uint8_t r) { return r != 0; })) {
    return;
  }
  double omega_squared = max_frequency_squared_bound(model, false, BarsIn::kSprings);
  if (!(omega_squared > 0.0)) {
    // No spring acts on a free node (a lone point tied to a pole): 50 Hz, stiff for anything seen.
    omega_squared = std::pow(2.0 * std::numbers::pi * 50.0, 2);
  }
  const double share_squared = kRigidTieFrequency * kRigidTieFrequency * omega_squared;
  for (Index t = 0; t < ties.count(); ++t) {
    if (ties.rigid[t] == 0) {
      continue;
    }
    const Index* nodes = &ties.nodes[4 * static_cast<std::size_t>(t)];
    double inverse_mass = model.node_inv_mass[nodes[0]];
    for (int k = 0; k < 3; ++k) {
      const double w = ties.weights[3 * static_cast<std::size_t>(t) + k];
      inverse_mass += w * w * model.node_inv_mass[nodes[k + 1]];
    }
    ties.stiffness[t] = share_squared / inverse_mass;
  }
}

}  // namespace

void add_ties(const SceneDescription& scene, const std::vector<TieRequest>& requests,
              Model& model) {
  Ties& ties = model.ties;
  for (const TieRequest& request : requests) {
    const AttachmentDesc& attachment = *request.attachment;
    const Index target = object_named(scene, attachment);
    if (request.nodes.empty()) {
      throw_user_error(attachment.nodes.loc,
                       "the nodes of object '{}' tied to '{}' select none of its nodes; check "
                       "the boxes' coordinates (metres, world space) or the indices",
                       request.object->name, attachment.target);
    }
    for (const Index node : request.nodes) {
      if (model.pinned(node)) {
        throw_user_error(attachment.nodes.loc,
                         "node {} of object '{}' is pinned and tied to '{}': a tied node moves "
                         "with what it is tied to; take it out of 'pinned'",
                         node - model.objects[model.node_object[node]].first_node,
                         request.object->name, attachment.target);
      }
      const NearestPoint point = nearest_point(model, target, model.node_initial_x[node]);
      if (point.nodes[0] < 0) {
        throw_user_error(attachment.target_loc, "object '{}' has no bar to tie to",
                         attachment.target);
      }
      ties.nodes.insert(ties.nodes.end(), {node, point.nodes[0], point.nodes[1], point.nodes[2]});
      ties.weights.insert(ties.weights.end(), point.weights.begin(), point.weights.end());
      const Vec3 offset = model.node_initial_x[node] - point.position;
      ties.offset.push_back(attachment.swings ? Vec3::Zero() : offset);
      ties.rest_length.push_back(attachment.swings ? point.distance : 0.0);
      ties.stiffness.push_back(attachment.stiffness.value_or(0.0));
      ties.rigid.push_back(attachment.stiffness ? 0 : 1);
      ties.break_force.push_back(attachment.break_force);
      ties.can_break = ties.can_break || attachment.break_force < kNoYield;
    }
  }
  stiffen_rigid_ties(model);
}

std::vector<std::uint8_t> tied_nodes(const Model& model) {
  std::vector<std::uint8_t> tied(static_cast<std::size_t>(model.node_count()), 0);
  for (Index t = 0; t < model.ties.count(); ++t) {
    tied[static_cast<std::size_t>(model.ties.nodes[4 * static_cast<std::size_t>(t)])] = 1;
  }
  return tied;
}

}  // namespace dinam
