#include "model/tied_contact.hpp"

#include <algorithm>
#include <vector>

#include "core/closest_points.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

double segment_distance(const Model& model, Index a, Index b) {
  const std::vector<Vec3>& x = model.node_initial_x;
  const Vec3& p0 = x[model.bar_nodes[2 * a]];
  const Vec3& p1 = x[model.bar_nodes[2 * a + 1]];
  const Vec3& q0 = x[model.bar_nodes[2 * b]];
  const Vec3& q1 = x[model.bar_nodes[2 * b + 1]];
  const SegmentPair closest = closest_points_of_segments(p0, p1, q0, q1);
  return ((p0 + closest.s * (p1 - p0)) - (q0 + closest.t * (q1 - q0))).norm();
}

double point_triangle_distance(const Model& model, Index node, const Index* corners) {
  const std::vector<Vec3>& x = model.node_initial_x;
  const std::array<double, 3> w =
      closest_point_of_triangle(x[node], x[corners[0]], x[corners[1]], x[corners[2]]);
  return (x[node] - (w[0] * x[corners[0]] + w[1] * x[corners[1]] + w[2] * x[corners[2]])).norm();
}

// The contact's bars and triangles of each object, and each node's bars and triangles.
struct ContactItems {
  std::vector<std::vector<Index>> bars_of_object;
  std::vector<std::vector<Index>> triangles_of_object;
  std::vector<std::vector<Index>> bars_of_node;
  std::vector<std::vector<Index>> triangles_of_node;
};

ContactItems contact_items(const Model& model) {
  const ObjectContact& contact = model.contact;
  ContactItems items;
  items.bars_of_object.resize(model.objects.size());
  items.triangles_of_object.resize(model.objects.size());
  items.bars_of_node.resize(static_cast<std::size_t>(model.node_count()));
  items.triangles_of_node.resize(static_cast<std::size_t>(model.node_count()));
  for (const Index b : contact.bars) {
    const Index n0 = model.bar_nodes[2 * b];
    items.bars_of_object[model.node_object[n0]].push_back(b);
    items.bars_of_node[n0].push_back(b);
    items.bars_of_node[model.bar_nodes[2 * b + 1]].push_back(b);
  }
  for (Index t = 0; t < static_cast<Index>(contact.triangle_face.size()); ++t) {
    const Index* corners = &contact.triangles[3 * static_cast<std::size_t>(t)];
    items.triangles_of_object[model.node_object[corners[0]]].push_back(t);
    for (int k = 0; k < 3; ++k) {
      items.triangles_of_node[corners[k]].push_back(t);
    }
  }
  return items;
}

}  // namespace

void leave_out_pairs_tied_at_rest(Model& model) {
  ObjectContact& contact = model.contact;
  contact.tied_bar_pairs.clear();
  contact.tied_point_triangles.clear();
  const Ties& ties = model.ties;
  if (ties.count() == 0) {
    return;
  }
  const ContactItems items = contact_items(model);
  for (Index t = 0; t < ties.count(); ++t) {
    const Index node = ties.nodes[4 * static_cast<std::size_t>(t)];
    const Index target = model.node_object[ties.nodes[4 * static_cast<std::size_t>(t) + 1]];
    // The tied node's bars against the target's bars.
    for (const Index a : items.bars_of_node[node]) {
      for (const Index b : items.bars_of_object[target]) {
        if (segment_distance(model, a, b) < contact.bar_radius[a] + contact.bar_radius[b]) {
          contact.tied_bar_pairs.push_back({std::min(a, b), std::max(a, b)});
        }
      }
    }
    // The tied node against the target's faces, and the target's nodes against the tied node's
    // faces.
    for (const Index triangle : items.triangles_of_object[target]) {
      const Index* corners = &contact.triangles[3 * static_cast<std::size_t>(triangle)];
      if (contact.point_radius[node] > 0.0 &&
          point_triangle_distance(model, node, corners) <
              contact.point_radius[node] + contact.triangle_radius[triangle]) {
        contact.tied_point_triangles.push_back({node, triangle});
      }
    }
    for (const Index triangle : items.triangles_of_node[node]) {
      const Index* corners = &contact.triangles[3 * static_cast<std::size_t>(triangle)];
      const ModelObject& other = model.objects[target];
      for (Index p = other.first_node; p < other.first_node + other.node_count; ++p) {
        if (contact.point_radius[p] > 0.0 &&
            point_triangle_distance(model, p, corners) <
                contact.point_radius[p] + contact.triangle_radius[triangle]) {
          contact.tied_point_triangles.push_back({p, triangle});
        }
      }
    }
  }
  for (auto* pairs : {&contact.tied_bar_pairs, &contact.tied_point_triangles}) {
    std::sort(pairs->begin(), pairs->end());
    pairs->erase(std::unique(pairs->begin(), pairs->end()), pairs->end());
  }
}

}  // namespace dinam
