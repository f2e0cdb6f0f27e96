#include "model/face_springs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/geometry.hpp"

namespace dinam {
namespace {

// A triangle is half of a rectangle when the angle facing its longest side is within this of a
// right angle (a quad mesh's cells, sheared or tapered a little, triangulated).
constexpr double kRightAngleSlack = 20.0 * std::numbers::pi / 180.0;
// On a triangle lattice each node has three lines of bending springs; bent about any axis they
// give Σ cos⁴ = 9/8 of one line's rigidity, so each line takes 8/9 of B w.
constexpr double kTriangleLatticeBending = 8.0 / 9.0;
constexpr double kStandardGravity = 9.81;  // m/s², for the bending length (B / ρ_A g)^⅓

// A piece of sheet or face whose springs are laid out as one: a face, or two triangles that make
// a rectangle. `loop` in welded ids.
struct FaceElement {
  std::vector<Index> loop;
  const MaterialDesc* material = nullptr;
  double area = 0.0;     // m²
  bool lattice = false;  // an unpaired triangle: every side takes w = A / L
};

// What the sheet faces around one edge spread onto its bar.
struct SheetEdge {
  double axial = 0.0;    // E A, N
  double bending = 0.0;  // E I and G J, N·m²
  double yield_force = 0.0;
  double yield_moment = 0.0;
  double breaking_force = 0.0;
  double breaking_strain = kNoYield;
  double radius = 0.0;
  bool on_face = false;  // a side of some sheet element, or the shared side of a pair
};

double loop_area(const std::vector<Index>& loop, const std::vector<Vec3>& x) {
  Vec3 twice = Vec3::Zero();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    twice += x[loop[i]].cross(x[loop[(i + 1) % loop.size()]]);
  }
  return 0.5 * twice.norm();
}

Index edge_index(const std::vector<Edge>& edges, Index a, Index b) {
  const Edge edge(std::min(a, b), std::max(a, b));
  const auto at = std::lower_bound(edges.begin(), edges.end(), edge);
  DINAM_CHECK(at != edges.end() && *at == edge);
  return static_cast<Index>(at - edges.begin());
}

// Adds `value` to a sum that stays infinite once any term is (a limit that one side lacks).
void add_limit(double& sum, double value) {
  sum = std::isinf(value) ? value : sum + value;
}

std::string where(const FileLoc& loc) {
  return loc.known() ? loc.to_string() : "dinam";
}

// The faces in welded ids, each with its material (a sheet's where one of its sides has one),
// and how many faces each edge is a side of.
struct FaceLoops {
  std::vector<std::vector<Index>> loops;
  std::vector<const MaterialDesc*> material;
  std::vector<Index> faces_on_edge;  // (n_edges)
};

FaceLoops face_loops(const CleanedMesh& clean, const WeldResult& weld,
                     const std::vector<Edge>& edges,
                     const std::vector<const MaterialDesc*>& edge_material) {
  FaceLoops faces;
  faces.loops.reserve(clean.faces.size());
  faces.faces_on_edge.assign(edges.size(), 0);
  for (const auto& face : clean.faces) {
    std::vector<Index> loop;
    loop.reserve(face.size());
    for (const Index v : face) {
      loop.push_back(weld.node_of_vertex[v]);
    }
    const MaterialDesc* material = nullptr;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index e = edge_index(edges, loop[i], loop[(i + 1) % loop.size()]);
      ++faces.faces_on_edge[e];
      if (material == nullptr || (!material->sheet && edge_material[e]->sheet)) {
        material = edge_material[e];
      }
    }
    faces.loops.push_back(std::move(loop));
    faces.material.push_back(material);
  }
  return faces;
}

// (n_faces) the other half of each sheet triangle that is half of a rectangle, or −1: two
// triangles whose right angles face their one shared side from either side of it.
std::vector<Index> rectangle_halves(const FaceLoops& faces, const std::vector<Edge>& edges,
                                    const std::vector<Vec3>& x) {
  std::vector<Index> half_on_edge(edges.size(), -1);  // the first such triangle on the edge
  std::vector<Index> partner(faces.loops.size(), -1);
  for (std::size_t f = 0; f < faces.loops.size(); ++f) {
    const std::vector<Index>& t = faces.loops[f];
    if (t.size() != 3 || !faces.material[f]->sheet) {
      continue;
    }
    int longest = 0;
    for (int i = 1; i < 3; ++i) {
      if ((x[t[(i + 1) % 3]] - x[t[i]]).squaredNorm() >
          (x[t[(longest + 1) % 3]] - x[t[longest]]).squaredNorm()) {
        longest = i;
      }
    }
    const Index a = t[longest];
    const Index b = t[(longest + 1) % 3];
    const Index p = t[(longest + 2) % 3];
    const Index e = edge_index(edges, a, b);
    if (std::abs(bend_angle(x[a], x[p], x[b]) - 0.5 * std::numbers::pi) > kRightAngleSlack ||
        faces.faces_on_edge[e] != 2) {
      continue;
    }
    if (half_on_edge[e] < 0) {
      half_on_edge[e] = static_cast<Index>(f);
      continue;
    }
    const std::vector<Index>& other = faces.loops[half_on_edge[e]];
    const Index q = other[0] != a && other[0] != b   ? other[0]
                    : other[1] != a && other[1] != b ? other[1]
                                                     : other[2];
    const Vec3 side = x[b] - x[a];
    if ((x[p] - x[a]).cross(side).dot((x[q] - x[a]).cross(side)) < 0.0) {  // a convex quad
      partner[f] = half_on_edge[e];
      partner[half_on_edge[e]] = static_cast<Index>(f);
    }
  }
  return partner;
}

// The elements springs are laid out on: each face, but a rectangle's two halves once, as it.
// `shared` (n_edges) marks the sides the halves share.
std::vector<FaceElement> face_elements(const FaceLoops& faces, const std::vector<Index>& partner,
                                       const std::vector<Edge>& edges, const std::vector<Vec3>& x,
                                       std::vector<Index>& shared) {
  std::vector<FaceElement> elements;
  for (std::size_t f = 0; f < faces.loops.size(); ++f) {
    FaceElement element;
    element.material = faces.material[f];
    const std::vector<Index>& t = faces.loops[f];
    if (partner[f] < 0) {
      element.loop = t;
      element.area = loop_area(t, x);
      element.lattice = t.size() == 3;
    } else if (partner[f] > static_cast<Index>(f)) {
      const std::vector<Index>& other = faces.loops[partner[f]];
      const auto apex = [](const std::vector<Index>& tri, const std::vector<Index>& beside) {
        for (const Index v : tri) {
          if (std::find(beside.begin(), beside.end(), v) == beside.end()) {
            return v;
          }
        }
        return tri[0];
      };
      // t's corners in its own order from its apex p: p, a, b; the quad runs p, a, q, b.
      const Index p = apex(t, other);
      const auto at = std::find(t.begin(), t.end(), p) - t.begin();
      const Index a = t[(at + 1) % 3];
      const Index b = t[(at + 2) % 3];
      element.loop = {p, a, apex(other, t), b};
      element.area = loop_area(t, x) + loop_area(other, x);
      shared[edge_index(edges, a, b)] = 1;
    } else {
      continue;  // laid out with its other half
    }
    elements.push_back(std::move(element));
  }
  return elements;
}

// Each corner of `element` a spring of stiffness shear × A / n on its angle.
void add_corner_springs(const FaceElement& element, double shear,
                        std::vector<CornerSpring>& corners) {
  const std::size_t n = element.loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    corners.push_back({element.loop[(i + n - 1) % n], element.loop[i], element.loop[(i + 1) % n],
                       shear * element.area / static_cast<double>(n)});
  }
}

// A wire material's face of four sides or more: the shear of the diagonal bar a triangulation
// would add, G = E A / (2 L_d), with E A the mean of its sides' bars.
double wire_face_shear(const FaceElement& element, const std::vector<Edge>& edges,
                       const std::vector<const MaterialDesc*>& edge_material,
                       const std::vector<Vec3>& x) {
  const std::vector<Index>& loop = element.loop;
  const std::size_t n = loop.size();
  double axial = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const MaterialDesc& m = *edge_material[edge_index(edges, loop[i], loop[(i + 1) % n])];
    axial += m.youngs_modulus * m.area / static_cast<double>(n);
  }
  const double diagonal =
      n == 4 ? 0.5 * ((x[loop[2]] - x[loop[0]]).norm() + (x[loop[3]] - x[loop[1]]).norm())
             : std::sqrt(2.0 * element.area);
  return axial / (2.0 * diagonal);
}

// Spreads a sheet element's stretch, bending, limits and mass onto its sides and corners.
void spread_sheet(const FaceElement& element, const std::vector<Edge>& edges,
                  const std::vector<Vec3>& x, std::vector<SheetEdge>& sheet,
                  std::vector<double>& vertex_mass) {
  const SheetDesc& s = *element.material->sheet;
  const std::size_t n = element.loop.size();
  const double share = element.lattice ? 1.0 : 2.0 / static_cast<double>(n);
  const double bending = element.lattice ? kTriangleLatticeBending : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Index c = element.loop[i];
    const Index e = edge_index(edges, c, element.loop[(i + 1) % n]);
    vertex_mass[c] += s.areal_density * element.area / static_cast<double>(n);
    const double width = share * element.area / (x[edges[e].second] - x[edges[e].first]).norm();
    SheetEdge& edge = sheet[e];
    edge.on_face = true;
    edge.axial += s.stretch_stiffness * width;
    edge.bending += bending * s.bending_rigidity * width;
    add_limit(edge.yield_force, s.yield_stretch * width);
    add_limit(edge.yield_moment, s.yield_bending * width);
    add_limit(edge.breaking_force, element.material->breaking_force * width);
    edge.breaking_strain = std::min(edge.breaking_strain, element.material->breaking_strain);
    edge.radius = std::max(edge.radius, 0.5 * s.thickness);
  }
}

// A sheet edge's bar as a material of its own: E = G = 1 and the section's A, I and J set to the
// rigidities, no density (the faces carry the mass).
MaterialDesc sheet_bar(const MaterialDesc& material, const SheetEdge& edge) {
  MaterialDesc bar;
  bar.preset = material.preset;
  bar.sheet = material.sheet;
  bar.loc = material.loc;
  bar.youngs_modulus = 1.0;
  bar.shear_modulus = 1.0;
  bar.area = edge.axial;
  bar.area_moment = edge.bending;
  bar.polar_moment = edge.bending;
  bar.wire_radius = edge.radius;
  const bool stiff = edge.axial > 0.0;  // not a rectangle's shared side
  bar.yield_axial_force = stiff ? edge.yield_force : kNoYield;
  bar.yield_bending_moment = stiff ? edge.yield_moment : kNoYield;
  bar.breaking_strain = stiff ? edge.breaking_strain : kNoYield;
  bar.breaking_force = stiff ? edge.breaking_force : kNoYield;
  return bar;
}

// The warnings of a sheet its mesh cannot show: folds under two bars wide, and triangles that
// shear as a lattice does rather than as the cloth. None for an object pinned whole (an obstacle,
// a collider following its track): it never bends or shears, whatever its mesh.
void warn_of_sheet_mesh(const ObjectDesc& object, std::vector<double> lengths,
                        Index lattice_triangles, std::vector<std::string>& warnings) {
  const MaterialDesc& material = object.material;
  if (lengths.empty() || !material.sheet || object.pins.all) {
    return;
  }
  const SheetDesc& s = *material.sheet;
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  const double bending_length =
      std::cbrt(s.bending_rigidity / (s.areal_density * kStandardGravity));
  if (bending_length < 0.5 * *middle) {
    warnings.push_back(fmt::format(
        "{}: warning: object '{}': the sheet's bending length (B / ρ_A g)^⅓ is {:.3g} mm, "
        "under half its bars (the median is {:.3g} mm): its folds are narrower than the mesh can "
        "bend, so it drapes in coarser folds than the cloth would; a mesh with bars of at most "
        "{:.2g} mm shows them",
        where(material.loc), object.name, 1e3 * bending_length, 1e3 * *middle,
        2e3 * bending_length));
  }
  if (lattice_triangles > 0 && s.shear_stiffness < 0.9 * 0.375 * s.stretch_stiffness) {
    warnings.push_back(fmt::format(
        "{}: warning: object '{}': {} of its triangles are not halves of a rectangle, so on them "
        "the sheet resists shear as much as a triangle lattice does ({:.3g} N/m, 3/8 of its "
        "stretch stiffness), not its shear_stiffness ({:.3g} N/m); a quad mesh, or one "
        "triangulated from quads, has the sheet's own shear",
        where(material.loc), object.name, lattice_triangles, 0.375 * s.stretch_stiffness,
        s.shear_stiffness));
  }
}

}  // namespace

FaceSprings face_springs(const ObjectDesc& object, const CleanedMesh& clean, const WeldResult& weld,
                         const std::vector<Edge>& edges,
                         std::vector<const MaterialDesc*> edge_material) {
  FaceSprings out;
  out.edge_material = std::move(edge_material);
  out.vertex_mass.assign(weld.nodes.size(), 0.0);
  const std::vector<Vec3>& x = weld.nodes;
  const bool any_sheet = std::any_of(out.edge_material.begin(), out.edge_material.end(),
                                     [](const MaterialDesc* m) { return m->sheet.has_value(); });
  if (any_sheet && clean.faces.empty()) {
    throw_user_error(object.material.loc,
                     "object '{}' has a sheet material, whose mass and stiffness are its faces', "
                     "but {} has no faces (only lines): give it a wire or rope material "
                     "(density, youngs_modulus, radius, or a preset such as hemp_rope)",
                     object.name, object.mesh_source);
  }
  const auto quads = std::count_if(clean.faces.begin(), clean.faces.end(),
                                   [](const auto& face) { return face.size() >= 4; });
  if (object.faces == FaceRole::kNet && quads > 0) {
    out.warnings.push_back(fmt::format(
        "{}: note: object '{}': faces: net leaves its {} faces of four sides or more without "
        "shear stiffness, as a net of cords is; a cloth needs faces: sheet (the default)",
        where(object.faces_loc), object.name, quads));
  }
  // Nothing to add where no face has a sheet material or four sides (a mesh of wire triangles,
  // a net): the common case of a large imported mesh costs nothing here.
  if (!any_sheet && (quads == 0 || object.faces == FaceRole::kNet)) {
    return out;
  }

  const FaceLoops faces = face_loops(clean, weld, edges, out.edge_material);
  std::vector<Index> shared(edges.size(), 0);
  const std::vector<FaceElement> elements =
      face_elements(faces, rectangle_halves(faces, edges, x), edges, x, shared);
  std::vector<SheetEdge> sheet(edges.size());
  Index lattice_triangles = 0;
  for (const FaceElement& element : elements) {
    if (element.material->sheet) {
      spread_sheet(element, edges, x, sheet, out.vertex_mass);
      lattice_triangles += element.lattice ? 1 : 0;
      if (element.loop.size() >= 4) {
        add_corner_springs(element, element.material->sheet->shear_stiffness, out.corners);
      }
    } else if (element.loop.size() >= 4 && object.faces == FaceRole::kSheet) {
      add_corner_springs(element, wire_face_shear(element, edges, out.edge_material, x),
                         out.corners);
    }
  }

  out.sheet_bars.reserve(edges.size());  // no reallocation: edge_material points into it
  Index loose = 0;
  std::vector<double> sheet_lengths;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const MaterialDesc* material = out.edge_material[e];
    if (!material->sheet) {
      continue;
    }
    SheetEdge& edge = sheet[e];
    if (shared[e] != 0) {  // a rectangle's shared side: no stiffness, but the sheet's radius
      edge.on_face = true;
      edge.radius = 0.5 * material->sheet->thickness;
    }
    loose += edge.on_face ? 0 : 1;
    out.sheet_bars.push_back(sheet_bar(*material, edge));
    out.edge_material[e] = &out.sheet_bars.back();
    if (edge.axial > 0.0) {
      sheet_lengths.push_back((x[edges[e].second] - x[edges[e].first]).norm());
    }
  }
  if (loose > 0) {
    throw_user_error(object.material.loc,
                     "object '{}': {} of its bars have a sheet material but are on no face of "
                     "{}: a sheet's stiffness and mass are its faces', so they would have none. "
                     "Give those edges a wire or rope material through 'parts' (by mesh_group, "
                     "mesh_material or nodes), or remove them from the mesh",
                     object.name, loose, object.mesh_source);
  }
  warn_of_sheet_mesh(object, std::move(sheet_lengths), lattice_triangles, out.warnings);
  return out;
}

}  // namespace dinam
