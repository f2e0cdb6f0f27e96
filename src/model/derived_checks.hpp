#pragma once
// The last line of defence against values that pass every range check yet combine into nothing a
// step can use: every mass, stiffness and length the model derived must be finite (and positive
// where it divides), and so must the frequency bound behind the stable step. A failure names the
// object and points at its material (or mesh), exit 2, before anything runs.
namespace dinam {

struct Model;
struct SceneDescription;

void check_derived_quantities(const Model& model, const SceneDescription& scene);

}  // namespace dinam
