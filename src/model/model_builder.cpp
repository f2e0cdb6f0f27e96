#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>
#include <type_traits>
#include <unordered_map>

#include "model/bar_sweep_order.hpp"
#include "model/contact_builder.hpp"
#include "model/derived_checks.hpp"
#include "model/edge_collapse.hpp"
#include "model/face_springs.hpp"
#include "model/frequency_bound.hpp"
#include "model/loose_pieces.hpp"
#include "model/mass_scaling.hpp"
#include "model/mesh_cleaning.hpp"
#include "model/model.hpp"
#include "model/model_arrays.hpp"
#include "model/model_spring_kinds.hpp"
#include "model/plausibility.hpp"
#include "model/spring_builders.hpp"
#include "model/step_aiming.hpp"
#include "model/tie_builder.hpp"
#include "model/vertex_welding.hpp"
#include "model/wind_load.hpp"
#include "scene/scene_description.hpp"

namespace dinam {
namespace {

// Collects the unique edges of an object's cleaned faces and lines in welded ids. A face
// contributes its closed loop, a line its open chain; an edge shared by two faces appears once.
std::vector<Edge> unique_edges(const CleanedMesh& mesh, const WeldResult& weld) {
  std::vector<Edge> edges;
  auto add = [&](Index va, Index vb) {
    const Index a = weld.node_of_vertex[va];
    const Index b = weld.node_of_vertex[vb];
    DINAM_CHECK(a != b);  // cleaning took zero-length sides out
    edges.emplace_back(std::min(a, b), std::max(a, b));
  };
  for (const auto& face : mesh.faces) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      add(face[i], face[(i + 1) % face.size()]);
    }
  }
  for (const auto& line : mesh.lines) {
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

// Where an object's mesh vertices went: the node of each vertex, −1 for vertices on no edge.
struct ObjectNodes {
  const ObjectDesc* desc = nullptr;
  Index object_id = 0;
  std::vector<Index> node_of_vertex;  // (n_vertices)
  BarMaterials bar_materials;         // (n_bars) the object's material or a part's
  // What its faces add (face_springs.hpp): bar_materials may point into its sheet_bars; its
  // corners in node ids.
  FaceSprings faces;
};
// The objects' list moves them as it grows, which keeps sheet_bars where bar_materials point.
static_assert(std::is_nothrow_move_constructible_v<ObjectNodes>);

// The nodes a selection names, in increasing order. A listed vertex on no edge is an error.
std::vector<Index> select_nodes(const NodeSelection& selection, const ObjectNodes& object,
                                const Model& model) {
  const ModelObject& info = model.objects[object.object_id];
  std::vector<bool> chosen(info.node_count, selection.all);
  for (const Index vertex : selection.vertex_ids) {
    const Index node = object.node_of_vertex[vertex];
    if (node < 0) {
      throw_user_error(selection.loc,
                       "object '{}': vertex {} is on no edge of the mesh, so it is not a node of "
                       "the structure",
                       info.name, vertex);
    }
    chosen[node - info.first_node] = true;
  }
  for (Index local = 0; local < info.node_count; ++local) {
    for (const BoxDesc& box : selection.boxes) {
      chosen[local] = chosen[local] || inside(box, model.node_initial_x[info.first_node + local]);
    }
  }
  std::vector<Index> nodes;
  for (Index local = 0; local < info.node_count; ++local) {
    if (chosen[local]) {
      nodes.push_back(info.first_node + local);
    }
  }
  return nodes;
}

// The part each edge belongs to (the last that holds it), or −1. A node selection holds the edges
// whose two ends it holds; a mesh material or group, the sides of its faces and lines.
std::vector<int> edge_parts(const ObjectDesc& object, const CleanedMesh& clean,
                            const WeldResult& weld, const std::vector<Edge>& edges,
                            const std::vector<Index>& node_of_welded, const ObjectNodes& nodes,
                            const Model& model) {
  std::vector<int> part_of_edge(edges.size(), -1);
  const ModelObject& info = model.objects[nodes.object_id];
  std::vector<bool> chosen(info.node_count);
  for (std::size_t p = 0; p < object.parts.size(); ++p) {
    const MaterialPartDesc& part = object.parts[p];
    const int id = static_cast<int>(p);
    if (!part.nodes.empty()) {
      std::fill(chosen.begin(), chosen.end(), false);
      for (const Index node : select_nodes(part.nodes, nodes, model)) {
        chosen[node - info.first_node] = true;
      }
      for (std::size_t e = 0; e < edges.size(); ++e) {
        if (chosen[node_of_welded[edges[e].first] - info.first_node] &&
            chosen[node_of_welded[edges[e].second] - info.first_node]) {
          part_of_edge[e] = id;
        }
      }
    }
    // The sides of the part's faces (closed loops) and lines (open chains).
    auto mark = [&](const std::vector<Index>& loop, bool closed) {
      const std::size_t sides = closed ? loop.size() : loop.size() - 1;
      for (std::size_t i = 0; i < sides; ++i) {
        const Index a = weld.node_of_vertex[loop[i]];
        const Index b = weld.node_of_vertex[loop[(i + 1) % loop.size()]];
        const Edge edge(std::min(a, b), std::max(a, b));
        const auto at = std::lower_bound(edges.begin(), edges.end(), edge);
        part_of_edge[static_cast<std::size_t>(at - edges.begin())] = id;
      }
    };
    for (const Index f : part.mesh_faces) {
      if (clean.kept_face[f] >= 0) {
        mark(clean.faces[clean.kept_face[f]], true);
      }
    }
    for (const Index l : part.mesh_lines) {
      if (clean.kept_line[l] >= 0) {
        mark(clean.lines[clean.kept_line[l]], false);
      }
    }
  }
  // A part that ends up with no bar is a selection that missed (a box beside the mesh, nodes
  // that no bar joins) or one a later part covers whole: either way not what was meant.
  std::vector<bool> holds_a_bar(object.parts.size(), false);
  for (const int id : part_of_edge) {
    if (id >= 0) {
      holds_a_bar[static_cast<std::size_t>(id)] = true;
    }
  }
  for (std::size_t p = 0; p < object.parts.size(); ++p) {
    if (!holds_a_bar[p]) {
      throw_user_error(object.parts[p].loc,
                       "this part of '{}' holds no bar: its selection takes none of the object's "
                       "{} bars with both ends, or a later part takes all it does. Check the "
                       "selection against 'dinam info' (node positions, the mesh's materials and "
                       "groups), or remove the part",
                       object.name, edges.size());
    }
  }
  return part_of_edge;
}

// Each welded vertex's number in the mesh file (RawMesh::source_vertex): the least of the vertices
// welded into it, −1 where none has one.
std::vector<Index> welded_sources(const RawMesh& mesh, const WeldResult& weld) {
  std::vector<Index> source(weld.nodes.size(), -1);
  for (std::size_t v = 0; v < mesh.source_vertex.size(); ++v) {
    Index& s = source[weld.node_of_vertex[v]];
    const Index candidate = mesh.source_vertex[v];
    if (candidate >= 0 && (s < 0 || candidate < s)) {
      s = candidate;
    }
  }
  return source;
}

// The order in which welded vertices become nodes: the file's own vertex order where the file has
// one (an OBJ's `v` lines), so that the caches' points are the file's vertices in order; then the
// rest in the order they first occur.
std::vector<Index> node_order(const std::vector<Index>& source_of_welded) {
  std::vector<Index> order(source_of_welded.size());
  for (std::size_t w = 0; w < order.size(); ++w) {
    order[w] = static_cast<Index>(w);
  }
  // Those with a number first, by it; then the rest, by id (a total order, so std::sort is as
  // stable as it needs to be, and takes no temporary buffer).
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    const Index sa = source_of_welded[a];
    const Index sb = source_of_welded[b];
    if ((sa < 0) != (sb < 0)) {
      return sa >= 0;
    }
    return sa != sb ? sa < sb : a < b;
  });
  return order;
}

std::string where_in_file(const ObjectDesc& object) {
  return object.mesh_loc.known() ? object.mesh_loc.to_string() : "dinam";
}

ObjectNodes add_object(const ObjectDesc& object, Index object_id, double weld_fraction,
                       Model& model) {
  WeldResult weld = weld_vertices(object.mesh.vertices, weld_tolerance(object.mesh.vertices));
  CleanedMesh clean = clean_mesh(object.mesh, weld.node_of_vertex);
  std::vector<Edge> edges = unique_edges(clean, weld);
  const EdgeCollapse collapse = collapse_short_edges(weld, edges, weld_fraction);
  if (collapse.merged_nodes > 0) {
    const std::size_t bars_before = edges.size();
    weld = collapse.weld;
    clean = clean_mesh(object.mesh, weld.node_of_vertex);
    edges = unique_edges(clean, weld);
    model.warnings.push_back(fmt::format(
        "{}: note: object '{}': collapsed {} bars shorter than {:g} of the median bar ({:.3g} m, "
        "`weld`), merging {} nodes into their neighbours",
        where_in_file(object), object.name, bars_before - edges.size(), weld_fraction,
        collapse.tolerance, collapse.merged_nodes));
  }
  if (edges.empty()) {
    throw_user_error(object.mesh_loc, "object '{}': {} has no edges left, so no bars{}",
                     object.name, object.mesh_source,
                     clean.changed() ? " (" + clean.summary() + ")" : "");
  }
  if (clean.changed()) {
    model.warnings.push_back(fmt::format("{}: warning: object '{}': {}", where_in_file(object),
                                         object.name, clean.summary()));
  }

  // Only welded vertices that end a bar become nodes.
  std::vector<Index> node_of_welded(weld.nodes.size(), -1);
  for (const auto& [a, b] : edges) {
    node_of_welded[a] = node_of_welded[b] = 0;
  }
  const std::vector<Index> source_of_welded = welded_sources(object.mesh, weld);
  ModelObject info;
  info.name = object.name;
  info.first_node = model.node_count();
  info.first_bar = model.bar_count();
  info.wire_radius = object.material.wire_radius;
  info.section_area = object.material.area;
  info.color = object.color;
  info.render_radius = object.render_radius.value_or(0.0);
  info.has_uvs = !object.mesh.uvs.empty();
  // Each node takes the texture coordinates of the first vertex welded into it.
  std::vector<Eigen::Vector2f> welded_uv(weld.nodes.size(), Eigen::Vector2f::Zero());
  std::vector<bool> uv_set(weld.nodes.size(), false);
  for (std::size_t v = 0; v < object.mesh.uvs.size(); ++v) {
    const Index w = weld.node_of_vertex[v];
    if (!uv_set[w]) {
      welded_uv[w] = object.mesh.uvs[v].cast<float>();
      uv_set[w] = true;
    }
  }
  Index next = info.first_node;
  for (const Index w : node_order(source_of_welded)) {
    if (node_of_welded[w] < 0) {
      continue;
    }
    node_of_welded[w] = next++;
    model.node_source_vertex.push_back(source_of_welded[w]);
    model.node_initial_x.push_back(weld.nodes[w]);
    model.node_initial_v.push_back(object.initial_velocity);
    model.node_mass.push_back(0.0);
    model.node_inv_mass.push_back(0.0);
    model.node_object.push_back(object_id);
    model.node_uv.push_back(welded_uv[w]);
  }
  info.node_count = next - info.first_node;
  info.source_vertex_count = object.mesh.source_vertex_count;
  info.bar_count = static_cast<Index>(edges.size());
  model.objects.push_back(std::move(info));
  ObjectNodes nodes{&object, object_id, {}, {}, {}};
  nodes.node_of_vertex.reserve(weld.node_of_vertex.size());
  for (const Index w : weld.node_of_vertex) {
    nodes.node_of_vertex.push_back(node_of_welded[w]);
  }

  // Each bar's material: the last part holding it, else the object's. Each bar's mass ρ A L0 goes
  // half to each end.
  const std::vector<int> part_of_edge =
      edge_parts(object, clean, weld, edges, node_of_welded, nodes, model);
  std::vector<const MaterialDesc*> edge_material(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    edge_material[e] =
        part_of_edge[e] >= 0 ? &object.parts[part_of_edge[e]].material : &object.material;
  }
  nodes.faces = face_springs(object, clean, weld, edges, std::move(edge_material));
  model.warnings.insert(model.warnings.end(), nodes.faces.warnings.begin(),
                        nodes.faces.warnings.end());
  for (CornerSpring& corner : nodes.faces.corners) {
    corner = {node_of_welded[corner.a], node_of_welded[corner.c], node_of_welded[corner.b],
              corner.stiffness};
  }
  for (std::size_t w = 0; w < weld.nodes.size(); ++w) {
    if (node_of_welded[w] >= 0) {
      model.node_mass[node_of_welded[w]] += nodes.faces.vertex_mass[w];
    }
  }
  if (object.material.sheet) {
    model.objects.back().wire_radius = 0.5 * object.material.sheet->thickness;
    model.objects.back().section_area = 0.0;
  }
  // Bars in the order of their nodes' ids, so that a thread's share is a few long runs (`edges`
  // stay in the order of welded ids, which the lookups above search).
  std::vector<std::size_t> bar_order(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    bar_order[e] = e;
  }
  const auto node_ids = [&](std::size_t e) {
    const Index a = node_of_welded[edges[e].first];
    const Index b = node_of_welded[edges[e].second];
    return std::pair{std::min(a, b), std::max(a, b)};
  };
  std::sort(bar_order.begin(), bar_order.end(),
            [&](std::size_t x, std::size_t y) { return node_ids(x) < node_ids(y); });
  for (const std::size_t e : bar_order) {
    const auto [n0, n1] = node_ids(e);
    const MaterialDesc& material = *nodes.faces.edge_material[e];
    nodes.bar_materials.push_back(&material);
    const double rest_length = (model.node_initial_x[n1] - model.node_initial_x[n0]).norm();
    model.bar_nodes.push_back(n0);
    model.bar_nodes.push_back(n1);
    model.bar_rest_length.push_back(rest_length);
    model.bar_axial_stiffness.push_back(material.youngs_modulus * material.area / rest_length);
    model.bar_yield_force.push_back(material.yield_axial_force);
    model.bar_radius.push_back(material.sheet ? material.wire_radius
                                              : std::sqrt(material.area / std::numbers::pi));
    model.bar_damping.push_back(0.0);  // set below, once the node masses are known
    const double half_mass = 0.5 * material.density * material.area * rest_length;
    model.node_mass[n0] += half_mass;
    model.node_mass[n1] += half_mass;
  }

  // Faces, with each corner's texture coordinates (a node on a seam has one per side) and the
  // material and groups the file gave each face, for the rest mesh the caches move.
  std::vector<Index> mesh_face_of_kept(clean.faces.size(), -1);
  for (std::size_t f = 0; f < clean.kept_face.size(); ++f) {
    if (clean.kept_face[f] >= 0) {
      mesh_face_of_kept[clean.kept_face[f]] = static_cast<Index>(f);
    }
  }
  const bool has_uvs = !object.mesh.uvs.empty();
  if (has_uvs && model.face_uv.size() < model.face_nodes.size()) {
    model.face_uv.resize(model.face_nodes.size(), Eigen::Vector2f::Zero());
  }
  model.objects.back().origins = object.mesh.origins;
  for (std::size_t k = 0; k < clean.faces.size(); ++k) {
    for (const Index vertex : clean.faces[k]) {
      model.face_nodes.push_back(node_of_welded[weld.node_of_vertex[vertex]]);
      if (has_uvs) {
        model.face_uv.push_back(object.mesh.uvs[vertex].cast<float>());
      } else if (!model.face_uv.empty()) {
        model.face_uv.emplace_back(Eigen::Vector2f::Zero());
      }
    }
    model.face_offsets.push_back(static_cast<Index>(model.face_nodes.size()));
    const Index mesh_face = mesh_face_of_kept[k];
    model.face_origin.push_back(
        object.mesh.face_origin.empty() || mesh_face < 0 ? -1 : object.mesh.face_origin[mesh_face]);
  }
  return nodes;
}

// "[x, y, z] … [x, y, z]", a box from its corners, for a message.
std::string span_text(const Vec3& lo, const Vec3& hi) {
  return fmt::format("[{:.4g}, {:.4g}, {:.4g}] … [{:.4g}, {:.4g}, {:.4g}]", lo.x(), lo.y(), lo.z(),
                     hi.x(), hi.y(), hi.z());
}

// "its box [x, y, z] … [x, y, z] lies", or its boxes', for a message.
std::string boxes_text(const std::vector<BoxDesc>& boxes) {
  std::vector<std::string> each;
  each.reserve(boxes.size());
  for (const BoxDesc& box : boxes) {
    each.push_back(span_text(box.min, box.max));
  }
  return fmt::format("{} {} {}", boxes.size() == 1 ? "its box" : "its boxes", fmt::join(each, ", "),
                     boxes.size() == 1 ? "lies" : "lie");
}

// The box the object's nodes span, "[x, y, z] … [x, y, z]".
std::string node_span_text(const ModelObject& info, const Model& model) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (Index node = info.first_node; node < info.first_node + info.node_count; ++node) {
    lo = lo.cwiseMin(model.node_initial_x[node]);
    hi = hi.cwiseMax(model.node_initial_x[node]);
  }
  return span_text(lo, hi);
}

// The driven nodes' tracks from the object's point cache (PinMotionDesc::track), each node on
// its first mesh vertex's.
void add_pin_track(const ObjectNodes& object, double fps, PinMotion& motion) {
  const PinMotionDesc& desc = object.desc->pin_motion;
  if (desc.track.empty()) {
    return;
  }
  const std::size_t vertices = object.node_of_vertex.size();
  std::unordered_map<Index, std::size_t> first_vertex;
  for (std::size_t v = vertices; v-- > 0;) {
    first_vertex[object.node_of_vertex[v]] = v;
  }
  std::vector<std::size_t> vertex_of_driven;
  vertex_of_driven.reserve(motion.nodes.size());
  for (const Index node : motion.nodes) {
    vertex_of_driven.push_back(first_vertex.at(node));
  }
  const std::size_t samples = desc.track.size() / vertices;
  motion.track.reserve(samples * motion.nodes.size());
  for (std::size_t s = 0; s < samples; ++s) {
    for (const std::size_t v : vertex_of_driven) {
      motion.track.push_back(desc.track[s * vertices + v]);
    }
  }
  motion.interval = desc.frames_per_sample / fps;
}

// Pins and initial velocities.
void add_object_conditions(const ObjectNodes& object, double fps, Model& model) {
  const ObjectDesc& desc = *object.desc;
  const ModelObject& info = model.objects[object.object_id];
  for (const VelocityGroupDesc& group : desc.velocity_groups) {
    for (const Index node : select_nodes(group.nodes, object, model)) {
      model.node_initial_v[node] = group.velocity;
    }
  }
  std::vector<Index> pinned;
  if (!desc.pins.empty()) {
    pinned = select_nodes(desc.pins, object, model);
    // A selection that holds no node is a box beside the mesh or a mesh in other units: the
    // object would fall unheld, which is never what `pinned` meant.
    if (pinned.empty()) {
      throw_user_error(desc.pins.loc,
                       "'pinned' of '{}' holds no node of its mesh: {} beside the mesh, whose "
                       "nodes span {} (m; check the mesh's units and placement, and its up axis), "
                       "or remove the key",
                       desc.name, boxes_text(desc.pins.boxes), node_span_text(info, model));
    }
  }
  for (Index node = info.first_node; node < info.first_node + info.node_count; ++node) {
    model.node_inv_mass[node] = 1.0 / model.node_mass[node];
  }
  for (const Index node : pinned) {
    model.node_inv_mass[node] = 0.0;
    model.node_initial_v[node].setZero();
  }
  if (desc.pin_motion.moving()) {
    model.pin_motions.push_back(
        {pinned, desc.pin_motion.displacement, desc.pin_motion.profile, {}, 0.0});
    add_pin_track(object, fps, model.pin_motions.back());
  }
}

// The axial dampers, from the node masses (after any mass scaling): c = 2ζ √(k μ), μ the reduced
// mass of the two ends, gives ζ of the bar's own axial vibration.
void add_axial_damping(const ObjectNodes& object, Model& model) {
  const ObjectDesc& desc = *object.desc;
  const ModelObject& info = model.objects[object.object_id];
  for (Index b = info.first_bar; b < info.first_bar + info.bar_count; ++b) {
    const double m0 = model.node_mass[model.bar_nodes[2 * b]];
    const double m1 = model.node_mass[model.bar_nodes[2 * b + 1]];
    const double reduced_mass = m0 * m1 / (m0 + m1);
    model.bar_damping[b] =
        desc.axial_damping.coefficient +
        2.0 * desc.axial_damping.ratio * std::sqrt(model.bar_axial_stiffness[b] * reduced_mass);
    model.any_bar_damping = model.any_bar_damping || model.bar_damping[b] != 0.0;
  }
}

// Which kinds of spring can yield; an elastic kind keeps no yield limits (model.hpp).
void note_yielding_kinds(Model& model) {
  for (const ModelSpringKind* kind : kModelSpringKinds) {
    std::vector<double>& limit = model.*kind->yield_limit;
    model.*kind->yields =
        std::any_of(limit.begin(), limit.end(), [](double y) { return y != kNoYield; });
    if (!(model.*kind->yields)) {
      limit = {};
    }
  }
}

// Marks the bars that are an edge of some mesh face, found through each node's bars.
void mark_bars_on_faces(Model& model) {
  model.bar_on_face.assign(model.bar_count(), 0);
  ModelObject everything;
  everything.node_count = model.node_count();
  everything.bar_count = model.bar_count();
  const NodeAdjacency bars_of_node = node_adjacency(model, everything);
  for (Index f = 0; f < model.face_count(); ++f) {
    const Index begin = model.face_offsets[f];
    const Index end = model.face_offsets[f + 1];
    for (Index k = begin; k < end; ++k) {
      const Index a = model.face_nodes[k];
      const Index b = model.face_nodes[k + 1 < end ? k + 1 : begin];
      for (const auto& [other, bar] : bars_of_node[a]) {
        if (other == b) {
          model.bar_on_face[bar] = 1;
        }
      }
    }
  }
}

void add_fields(const SceneDescription& scene, const std::vector<ObjectNodes>& objects,
                Model& model) {
  for (const FieldForceDesc& desc : scene.fields) {
    FieldForce field{desc.value, desc.per_unit_mass, {}, desc.profile};
    for (const ObjectNodes& object : objects) {
      if (!desc.object.empty() && object.desc->name != desc.object) {
        continue;
      }
      NodeSelection selection = desc.nodes;
      selection.all = selection.all || desc.nodes.empty();
      const std::vector<Index> nodes = select_nodes(selection, object, model);
      field.nodes.insert(field.nodes.end(), nodes.begin(), nodes.end());
    }
    model.fields.push_back(std::move(field));
  }
}

// Every object's attachments, their nodes resolved.
std::vector<TieRequest> tie_requests(const std::vector<ObjectNodes>& objects, const Model& model) {
  std::vector<TieRequest> requests;
  for (const ObjectNodes& object : objects) {
    for (const AttachmentDesc& attachment : object.desc->attachments) {
      requests.push_back({object.desc, &attachment, select_nodes(attachment.nodes, object, model)});
    }
  }
  return requests;
}

// The arrays grew by push_back, to up to twice their length: give the spare capacity back, since
// a model lives as long as its run.
void release_spare_capacity(Model& model) {
  for_each_model_array(model, [](std::string_view, auto& array) { array.shrink_to_fit(); });
}

Model build_model_once(const SceneDescription& scene, const ShortBarPlan& plan) {
  Model model;
  model.gravity = scene.gravity;
  model.global_damping = scene.global_damping;
  model.integrator = scene.integrator;
  model.implicit_scheme = scene.implicit_scheme;
  model.settle = {scene.settle.enabled,  scene.settle.method,  scene.settle.duration,
                  scene.settle.residual, scene.settle.damping, scene.settle.loc};
  model.face_offsets.push_back(0);
  std::vector<ObjectNodes> objects;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const ObjectDesc& object = scene.objects[i];
    objects.push_back(add_object(object, static_cast<Index>(i),
                                 std::max(object.weld_fraction, plan.weld_floor), model));
  }
  mark_bars_on_faces(model);  // before the bending springs, which pair bars by it
  for (const ObjectNodes& object : objects) {
    add_object_conditions(object, scene.fps, model);
    const ModelObject& info = model.objects[object.object_id];
    const NodeAdjacency adjacency = node_adjacency(model, info);
    const Index first_bend = model.bend_count();
    add_bending_springs(object.bar_materials, object.desc->bending_pairs, info, adjacency, model);
    if (object.desc->pins_clamped) {
      add_clamps(object.bar_materials, info, adjacency, model, first_bend);
    }
    add_corner_springs(object.faces.corners, model);
    if (object.desc->torsion) {
      add_torsion_springs(object.bar_materials, info, adjacency, model);
    } else {
      model.bars_without_torsion += info.bar_count;
    }
  }
  scale_masses(scene, plan, model);
  for (const ObjectNodes& object : objects) {
    add_axial_damping(object, model);
  }
  if (!model.any_bar_damping) {
    model.bar_damping = {};  // no damper anywhere: nothing to keep (model.hpp)
  }
  std::vector<BarMaterials> bar_materials;
  bar_materials.reserve(objects.size());
  for (const ObjectNodes& object : objects) {
    bar_materials.push_back(object.bar_materials);
  }
  add_tearing(bar_materials, model);
  add_fields(scene, objects, model);
  add_ties(scene, tie_requests(objects, model), model);  // before the contacts, which bound by them
  add_wind(scene, model);
  add_ground_contact(scene, model);
  add_object_contact(scene, model);
  note_yielding_kinds(model);
  if (model.bars_are_constraints()) {
    // Contact within an object fights the bars' projection: a rope in a heap, its turns pressed
    // on each other, kept moving at 5 m/s where central differences brought it to rest, the
    // projection taking out a thousand times the energy it had.
    for (std::size_t k = 0; k < model.contact.object_self.size(); ++k) {
      if (model.contact.object_self[k] != 0) {
        throw_user_error(scene.integrator_loc,
                         "'integrator: xpbd' holds the bars as constraints, which do not work with "
                         "contact within an object (object '{}' has contact with itself); use "
                         "'integrator: central_difference' for it",
                         model.objects[k].name);
      }
    }
    model.bar_sweep_order = bar_sweep_order(model);
  }
  note_implausible_values(scene, model);
  note_loose_pieces(scene, model);
  release_spare_capacity(model);
  check_derived_quantities(model, scene);
  return model;
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
  return build_aiming_at_step(
      scene, [&](const ShortBarPlan& plan) { return build_model_once(scene, plan); });
}

}  // namespace dinam
