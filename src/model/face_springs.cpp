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

  // Each face in welded ids, with its material: a sheet's where one of its sides has one.
  std::vector<std::vector<Index>> loops;
  std::vector<const MaterialDesc*> face_material;
  std::vector<Index> faces_on_edge(edges.size(), 0);
  for (const auto& face : clean.faces) {
    std::vector<Index> loop;
    for (const Index v : face) {
      loop.push_back(weld.node_of_vertex[v]);
    }
    const MaterialDesc* material = nullptr;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index e = edge_index(edges, loop[i], loop[(i + 1) % loop.size()]);
      ++faces_on_edge[e];
      if (material == nullptr || (!material->sheet && out.edge_material[e]->sheet)) {
        material = out.edge_material[e];
      }
    }
    loops.push_back(std::move(loop));
    face_material.push_back(material);
  }

  // Sheet triangles that are halves of a rectangle, by the side facing their right angle.
  std::vector<Index> half_on_edge(edges.size(), -1);  // the first such triangle on the edge
  std::vector<Index> partner(loops.size(), -1);
  for (std::size_t f = 0; f < loops.size(); ++f) {
    const std::vector<Index>& t = loops[f];
    if (t.size() != 3 || !face_material[f]->sheet) {
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
    if (std::abs(bend_angle(x[a], x[p], x[b]) - 0.5 * std::numbers::pi) > kRightAngleSlack) {
      continue;
    }
    const Index e = edge_index(edges, a, b);
    if (faces_on_edge[e] != 2) {
      continue;
    }
    if (half_on_edge[e] < 0) {
      half_on_edge[e] = static_cast<Index>(f);
      continue;
    }
    // The two right angles on opposite sides of their shared side: a convex quad.
    const std::vector<Index>& s = loops[half_on_edge[e]];
    const Index q = s[0] != a && s[0] != b ? s[0] : (s[1] != a && s[1] != b ? s[1] : s[2]);
    const Vec3 side = x[b] - x[a];
    if ((x[p] - x[a]).cross(side).dot((x[q] - x[a]).cross(side)) < 0.0) {
      partner[f] = half_on_edge[e];
      partner[half_on_edge[e]] = static_cast<Index>(f);
    }
  }

  // The elements: each face, but a pair of halves once, as its quad.
  std::vector<FaceElement> elements;
  std::vector<SheetEdge> sheet(edges.size());
  for (std::size_t f = 0; f < loops.size(); ++f) {
    FaceElement element;
    element.material = face_material[f];
    if (partner[f] >= 0) {
      if (partner[f] < static_cast<Index>(f)) {
        continue;
      }
      const std::vector<Index>& t = loops[f];
      const std::vector<Index>& s = loops[partner[f]];
      const auto apex = [](const std::vector<Index>& tri, const std::vector<Index>& other) {
        for (const Index v : tri) {
          if (std::find(other.begin(), other.end(), v) == other.end()) {
            return v;
          }
        }
        return tri[0];
      };
      const Index p = apex(t, s);
      const Index q = apex(s, t);
      // t's corners in its own order from p: p, a, b; the quad runs p, a, q, b.
      const auto at = std::find(t.begin(), t.end(), p) - t.begin();
      const Index a = t[(at + 1) % 3];
      const Index b = t[(at + 2) % 3];
      element.loop = {p, a, q, b};
      element.area = loop_area(t, x) + loop_area(s, x);
      SheetEdge& shared = sheet[edge_index(edges, a, b)];
      shared.on_face = true;
      shared.radius = std::max(shared.radius, 0.5 * element.material->sheet->thickness);
    } else {
      element.loop = loops[f];
      element.area = loop_area(loops[f], x);
      element.lattice = loops[f].size() == 3;
    }
    elements.push_back(std::move(element));
  }

  Index lattice_triangles = 0;
  Index net_faces = 0;
  for (const FaceElement& element : elements) {
    const std::size_t n = element.loop.size();
    const double area = element.area;
    const auto corner_springs = [&](double shear) {
      for (std::size_t i = 0; i < n; ++i) {
        out.corners.push_back({element.loop[(i + n - 1) % n], element.loop[i],
                               element.loop[(i + 1) % n], shear * area / static_cast<double>(n)});
      }
    };
    if (!element.material->sheet) {
      if (n < 4) {
        continue;  // a triangle of wires is rigid in its plane already
      }
      if (object.faces == FaceRole::kNet) {
        ++net_faces;
        continue;
      }
      // The shear of the diagonal bar a triangulation would add: G = E A / (2 L_d).
      double axial = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        const MaterialDesc& m =
            *out.edge_material[edge_index(edges, element.loop[i], element.loop[(i + 1) % n])];
        axial += m.youngs_modulus * m.area / static_cast<double>(n);
      }
      const double diagonal = n == 4 ? 0.5 * ((x[element.loop[2]] - x[element.loop[0]]).norm() +
                                              (x[element.loop[3]] - x[element.loop[1]]).norm())
                                     : std::sqrt(2.0 * area);
      corner_springs(axial / (2.0 * diagonal));
      continue;
    }
    const SheetDesc& s = *element.material->sheet;
    const double share = element.lattice ? 1.0 : 2.0 / static_cast<double>(n);
    const double bending = element.lattice ? kTriangleLatticeBending : 1.0;
    lattice_triangles += element.lattice ? 1 : 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Index c = element.loop[i];
      const Index e = edge_index(edges, c, element.loop[(i + 1) % n]);
      out.vertex_mass[c] += s.areal_density * area / static_cast<double>(n);
      const double width = share * area / (x[edges[e].second] - x[edges[e].first]).norm();
      SheetEdge& edge = sheet[e];
      edge.on_face = true;
      edge.axial += s.stretch_stiffness * width;
      edge.bending += bending * s.bending_rigidity * width;
      add_limit(edge.yield_force, s.yield_stretch * width);
      add_limit(edge.yield_moment, s.yield_bending * width);
      add_limit(edge.breaking_force, element.material->breaking_force * width);
      edge.breaking_strain = std::min(edge.breaking_strain, element.material->breaking_strain);
      edge.radius = std::max(edge.radius, 0.5 * s.thickness);
      out.sheet_thickness = std::max(out.sheet_thickness, s.thickness);
    }
    if (n >= 4) {
      corner_springs(s.shear_stiffness);
    }
  }

  // Each sheet edge's bar, as a material of its own: E = G = 1 and the section's A, I, J set to
  // the rigidities, no density (the faces carry the mass).
  out.sheet_bars.reserve(edges.size());
  Index loose = 0;
  std::vector<double> sheet_lengths;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const MaterialDesc* material = out.edge_material[e];
    if (!material->sheet) {
      continue;
    }
    const SheetEdge& edge = sheet[e];
    loose += edge.on_face ? 0 : 1;
    MaterialDesc bar;
    bar.preset = material->preset;
    bar.sheet = material->sheet;
    bar.loc = material->loc;
    bar.youngs_modulus = 1.0;
    bar.shear_modulus = 1.0;
    bar.area = edge.axial;
    bar.area_moment = edge.bending;
    bar.polar_moment = edge.bending;
    bar.wire_radius = edge.radius;
    bar.yield_axial_force = edge.axial > 0.0 ? edge.yield_force : kNoYield;
    bar.yield_bending_moment = edge.bending > 0.0 ? edge.yield_moment : kNoYield;
    bar.breaking_strain = edge.axial > 0.0 ? edge.breaking_strain : kNoYield;
    bar.breaking_force = edge.axial > 0.0 ? edge.breaking_force : kNoYield;
    out.sheet_bars.push_back(bar);
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

  // What the mesh cannot show of the sheet, and the shear the scene took away.
  const MaterialDesc& first = object.material;
  if (!sheet_lengths.empty() && first.sheet) {
    const auto middle =
        sheet_lengths.begin() + static_cast<std::ptrdiff_t>(sheet_lengths.size() / 2);
    std::nth_element(sheet_lengths.begin(), middle, sheet_lengths.end());
    const double bending_length =
        std::cbrt(first.sheet->bending_rigidity / (first.sheet->areal_density * kStandardGravity));
    if (bending_length < 0.5 * *middle) {
      out.warnings.push_back(fmt::format(
          "{}: warning: object '{}': the sheet's bending length (B / ρ_A g)^⅓ is {:.3g} mm, "
          "under half its bars (the median is {:.3g} mm): its folds are narrower than the mesh "
          "can bend, so it drapes in coarser folds than the cloth would; a mesh with bars of "
          "at most {:.2g} mm shows them",
          where(first.loc), object.name, 1e3 * bending_length, 1e3 * *middle,
          2e3 * bending_length));
    }
    const SheetDesc& s = *first.sheet;
    if (lattice_triangles > 0 && s.shear_stiffness < 0.9 * 0.375 * s.stretch_stiffness) {
      out.warnings.push_back(fmt::format(
          "{}: warning: object '{}': {} of its triangles are not halves of a rectangle, so on them "
          "the sheet resists shear as much as a triangle lattice does ({:.3g} N/m, 3/8 of its "
          "stretch stiffness), not its shear_stiffness ({:.3g} N/m); a quad mesh, or one "
          "triangulated from quads, has the sheet's own shear",
          where(first.loc), object.name, lattice_triangles, 0.375 * s.stretch_stiffness,
          s.shear_stiffness));
    }
  }
  if (net_faces > 0) {
    out.warnings.push_back(fmt::format(
        "{}: note: object '{}': faces: net leaves its {} faces of four sides or more without "
        "shear stiffness, as a net of cords is; a cloth needs faces: sheet (the default)",
        where(object.faces_loc), object.name, net_faces));
  }
  return out;
}

}  // namespace dinam
