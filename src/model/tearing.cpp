#include "core/error.hpp"
#include "model/bar_lookup.hpp"
#include "model/model_spring_kinds.hpp"
#include "model/spring_builders.hpp"

namespace dinam {
namespace {

// Inverts (spring → bars) lists into bar → entries, as offsets and ids.
void invert(const std::vector<std::pair<Index, Index>>& bar_entry, Index bar_count,
            std::vector<Index>& offsets, std::vector<Index>& entries) {
  offsets.assign(static_cast<std::size_t>(bar_count) + 1, 0);
  for (const auto& [bar, entry] : bar_entry) {
    ++offsets[static_cast<std::size_t>(bar) + 1];
  }
  for (std::size_t b = 0; b < static_cast<std::size_t>(bar_count); ++b) {
    offsets[b + 1] += offsets[b];
  }
  entries.resize(bar_entry.size());
  std::vector<Index> next(offsets.begin(), offsets.end() - 1);
  for (const auto& [bar, entry] : bar_entry) {  // in spring order: deterministic
    entries[static_cast<std::size_t>(next[static_cast<std::size_t>(bar)]++)] = entry;
  }
}

}  // namespace

void add_tearing(const std::vector<BarMaterials>& materials, Model& model) {
  bool any = false;
  for (const BarMaterials& object : materials) {
    for (const MaterialDesc* material : object) {
      any = any || material->can_break();
    }
  }
  if (!any) {
    return;
  }
  model.bar_breaking_strain.assign(model.bar_count(), kNoYield);
  model.bar_breaking_force.assign(model.bar_count(), kNoYield);
  for (std::size_t o = 0; o < materials.size(); ++o) {
    const ModelObject& object = model.objects[o];
    for (Index b = 0; b < object.bar_count; ++b) {
      const MaterialDesc& material = *materials[o][static_cast<std::size_t>(b)];
      model.bar_breaking_strain[object.first_bar + b] = material.breaking_strain;
      model.bar_breaking_force[object.first_bar + b] = material.breaking_force;
    }
  }

  // Every spring stands on the bars whose angles or twist it measures.
  const BarLookup lookup(model);
  std::vector<std::pair<Index, Index>> bar_spring;  // (bar, 3 × spring + torn code)
  for (const ModelSpringKind* kind : kModelSpringKinds) {
    if (kind->add_bars_stood_on == nullptr) {
      continue;  // the bar's own spring
    }
    std::vector<BarSpring> stood_on;
    kind->add_bars_stood_on(model, lookup, stood_on);
    for (const auto& [bar, spring] : stood_on) {
      bar_spring.emplace_back(bar, 3 * spring + kind->torn_code);
    }
  }
  for (const auto& [bar, entry] : bar_spring) {
    DINAM_CHECK(bar >= 0);
  }
  invert(bar_spring, model.bar_count(), model.bar_spring_offsets, model.bar_springs);

  std::vector<std::pair<Index, Index>> bar_face;
  for (Index f = 0; f < model.face_count(); ++f) {
    const Index begin = model.face_offsets[f];
    const Index end = model.face_offsets[f + 1];
    for (Index k = begin; k < end; ++k) {
      const Index bar =
          lookup.find(model.face_nodes[k], model.face_nodes[k + 1 < end ? k + 1 : begin]);
      if (bar >= 0) {
        bar_face.emplace_back(bar, f);
      }
    }
  }
  invert(bar_face, model.bar_count(), model.bar_face_offsets, model.bar_faces);
}

}  // namespace dinam
