#include <algorithm>

#include "model/model.hpp"
#include "model/vertex_welding.hpp"
#include "scene/scene_description.hpp"

namespace dinam {
namespace {

using Edge = std::pair<Index, Index>;  // welded ids, first < second

// Collects the unique edges of an object's faces and lines in welded ids. A face contributes its
// closed loop, a line its open chain; an edge shared by two faces appears once.
std::vector<Edge> unique_edges(const ObjectDesc& object, const WeldResult& weld) {
  std::vector<Edge> edges;
  auto add = [&](Index va, Index vb) {
    const Index a = weld.node_of_vertex[va];
    const Index b = weld.node_of_vertex[vb];
    if (a == b) {
      const Vec3& p = object.mesh.vertices[va];
      throw_user_error(object.mesh_loc,
                       "object '{}': the mesh edge between vertices {} and {} has zero length "
                       "(both at ({:g}, {:g}, {:g})); a bar needs two distinct ends, so remove the "
                       "degenerate face or line from the mesh",
                       object.name, va, vb, p.x(), p.y(), p.z());
    }
    edges.emplace_back(std::min(a, b), std::max(a, b));
  };
  for (const auto& face : object.mesh.faces) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      add(face[i], face[(i + 1) % face.size()]);
    }
  }
  for (const auto& line : object.mesh.lines) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      add(line[i], line[i + 1]);
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

bool inside(const BoxDesc& box, const Vec3& p) {
  return (p.array() >= box.min.array()).all() && (p.array() <= box.max.array()).all();
}

void add_object(const ObjectDesc& object, Index object_id, Model& model) {
  const WeldResult weld = weld_vertices(object.mesh.vertices, weld_tolerance(object.mesh.vertices));
  const std::vector<Edge> edges = unique_edges(object, weld);
  if (edges.empty()) {
    throw_user_error(object.mesh_loc, "object '{}': the mesh has no edges, so no bars",
                     object.name);
  }

  // Only welded vertices that end a bar become nodes; ids stay in first-occurrence order.
  std::vector<Index> node_of_welded(weld.nodes.size(), -1);
  for (const auto& [a, b] : edges) {
    node_of_welded[a] = node_of_welded[b] = 0;
  }
  ModelObject info;
  info.name = object.name;
  info.first_node = model.node_count();
  info.first_bar = model.bar_count();
  info.wire_radius = object.material.wire_radius;
  info.section_area = object.material.area;
  info.color = object.color;
  info.render_radius = object.render_radius.value_or(0.0);
  Index next = info.first_node;
  for (std::size_t w = 0; w < weld.nodes.size(); ++w) {
    if (node_of_welded[w] < 0) {
      continue;
    }
    node_of_welded[w] = next++;
    model.node_initial_x.push_back(weld.nodes[w]);
    model.node_initial_v.push_back(object.initial_velocity);
    model.node_mass.push_back(0.0);
    model.node_inv_mass.push_back(0.0);
    model.node_object.push_back(object_id);
  }
  info.node_count = next - info.first_node;

  // Each bar's mass ρ A L0 goes half to each end.
  const MaterialDesc& material = object.material;
  for (const auto& [a, b] : edges) {
    const Index n0 = node_of_welded[a];
    const Index n1 = node_of_welded[b];
    const double rest_length = (model.node_initial_x[n1] - model.node_initial_x[n0]).norm();
    model.bar_nodes.push_back(n0);
    model.bar_nodes.push_back(n1);
    model.bar_rest_length.push_back(rest_length);
    model.bar_axial_stiffness.push_back(material.youngs_modulus * material.area / rest_length);
    const double half_mass = 0.5 * material.density * material.area * rest_length;
    model.node_mass[n0] += half_mass;
    model.node_mass[n1] += half_mass;
  }
  info.bar_count = static_cast<Index>(edges.size());

  // Pins: the union of `all`, vertex ids and boxes. A pinned node never moves.
  std::vector<bool> pinned(info.node_count, object.pins.all);
  for (const Index vertex : object.pins.vertex_ids) {
    const Index node = node_of_welded[weld.node_of_vertex[vertex]];
    if (node < 0) {
      throw_user_error(object.pins.loc,
                       "object '{}': pinned vertex {} is on no edge of the mesh, so it is not a "
                       "node of the structure",
                       object.name, vertex);
    }
    pinned[node - info.first_node] = true;
  }
  for (Index local = 0; local < info.node_count; ++local) {
    const Vec3& p = model.node_initial_x[info.first_node + local];
    for (const BoxDesc& box : object.pins.boxes) {
      pinned[local] = pinned[local] || inside(box, p);
    }
  }
  for (Index local = 0; local < info.node_count; ++local) {
    const Index node = info.first_node + local;
    if (pinned[local]) {
      model.node_initial_v[node].setZero();
    } else {
      model.node_inv_mass[node] = 1.0 / model.node_mass[node];
    }
  }

  for (const auto& face : object.mesh.faces) {
    for (const Index vertex : face) {
      model.face_nodes.push_back(node_of_welded[weld.node_of_vertex[vertex]]);
    }
    model.face_offsets.push_back(static_cast<Index>(model.face_nodes.size()));
  }
  model.objects.push_back(std::move(info));
}

}  // namespace

double Model::total_mass() const {
  double mass = 0.0;
  for (const double m : node_mass) {
    mass += m;
  }
  return mass;
}

Model build_model(const SceneDescription& scene) {
  Model model;
  model.gravity = scene.gravity;
  model.face_offsets.push_back(0);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    add_object(scene.objects[i], static_cast<Index>(i), model);
  }
  return model;
}

}  // namespace dinam
