#pragma once
// Named materials (`material: {preset: NAME}`): the fabrics, ropes, cables and wires users reach
// for, each a set of material keys with their values and where the values come from. A scene's
// own keys beside `preset` override the preset's one by one. docs/materials.md lists the same
// table for users; the Blender add-on offers the same names.
#include <string_view>
#include <utility>
#include <vector>

namespace dinam {

struct MaterialDesc;

struct MaterialPreset {
  const char* name;
  bool sheet;  // a sheet (areal values) rather than a wire or rope (a section)
  std::vector<std::pair<const char*, double>> values;  // material keys, SI units
  const char* source;                                  // where the values come from

  // The value of `key`, or nullptr when the preset does not set it.
  const double* find(std::string_view key) const;
};

// Every preset, in the order docs/materials.md gives them.
const std::vector<MaterialPreset>& material_presets();

// The preset called `name`, or nullptr.
const MaterialPreset* find_material_preset(std::string_view name);

// A material's values as the scene keys name them, after its preset and the scene's keys are
// resolved (what `dinam info` prints): key, value, unit.
struct MaterialValue {
  const char* key;
  double value;
  const char* unit;
};
std::vector<MaterialValue> resolved_material_values(const MaterialDesc& material);

}  // namespace dinam
