#include "model/derived_checks.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "model/frequency_bound.hpp"
#include "model/model.hpp"
#include "model/model_spring_kinds.hpp"

namespace dinam {
namespace {

bool usable(double value, bool must_be_positive) {
  return std::isfinite(value) && (must_be_positive ? value > 0.0 : value >= 0.0);
}

// The first of `values[first … end)` that is not usable, or -1.
Index first_unusable(const std::vector<double>& values, Index first, Index end,
                     bool must_be_positive) {
  for (Index i = first; i < end; ++i) {
    if (!usable(values[i], must_be_positive)) {
      return i;
    }
  }
  return -1;
}

[[noreturn]] void refuse(const ObjectDesc& desc, const FileLoc& where, const std::string& what,
                         double value) {
  // A sheet's mass and stiffness are its faces': its keys, and the faces' areas, are to check.
  const char* advice =
      desc.material.sheet
          ? "the sheet's values and its faces combine to nothing or beyond double precision "
            "(check areal_density and stretch_stiffness against the mesh's size, and that its "
            "faces have an area: a face whose corners lie on one line carries no cloth)"
          : "the material's values combine beyond double precision (check density, "
            "youngs_modulus and the section against the mesh's size)";
  throw_user_error(where, "object '{}': {} is {:g}, which no step can use; {}", desc.name, what,
                   value, advice);
}

}  // namespace

void check_derived_quantities(const Model& model, const SceneDescription& scene) {
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ModelObject& object = model.objects[o];
    const ObjectDesc& desc = scene.objects[o];
    const FileLoc& material = desc.material.loc;
    const Index node_end = object.first_node + object.node_count;
    const Index bar_end = object.first_bar + object.bar_count;
    if (const Index i = first_unusable(model.node_mass, object.first_node, node_end, true);
        i >= 0) {
      refuse(desc, material, "the mass of node " + std::to_string(i - object.first_node),
             model.node_mass[i]);
    }
    if (const Index b = first_unusable(model.bar_rest_length, object.first_bar, bar_end, true);
        b >= 0) {
      refuse(desc, desc.mesh_loc, "the length of bar " + std::to_string(b - object.first_bar),
             model.bar_rest_length[b]);
    }
    // A sheet's two triangles that make a rectangle share a side of no stiffness
    // (face_springs.hpp).
    bool sheet = desc.material.sheet.has_value();
    for (const MaterialPartDesc& part : desc.parts) {
      sheet = sheet || part.material.sheet.has_value();
    }
    if (const Index b =
            first_unusable(model.bar_axial_stiffness, object.first_bar, bar_end, !sheet);
        b >= 0) {
      refuse(desc, material,
             "the axial stiffness E·A/L₀ of bar " + std::to_string(b - object.first_bar),
             model.bar_axial_stiffness[b]);
    }
  }
  // The springs of every kind, and the ground's, span one object each.
  const auto check_spring_values = [&](const std::vector<double>& values, const char* what) {
    if (const Index k = first_unusable(values, 0, static_cast<Index>(values.size()), false);
        k >= 0) {
      throw_user_error(scene.objects.front().material.loc,
                       "a stiffness of the model's {} is {:g}; the materials' values combine "
                       "beyond double precision (check density, youngs_modulus and the section)",
                       what, values[k]);
    }
  };
  for (const ModelSpringKind* kind : kModelSpringKinds) {
    check_spring_values(model.*kind->stiffness, kind->name);
  }
  check_spring_values(model.ground.node_stiffness, "ground contact");
  check_spring_values(model.ground.node_damping, "ground contact dampers");
  const double omega_squared = max_frequency_squared_bound(model, true);
  if (!std::isfinite(omega_squared)) {
    throw_user_error(scene.objects.front().material.loc,
                     "the model's highest frequency is not finite, so no time step is stable; the "
                     "materials' values combine beyond double precision");
  }
}

}  // namespace dinam
