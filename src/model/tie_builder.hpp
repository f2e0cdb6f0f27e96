#pragma once
// Attachments (`attach`) made into ties (model.hpp's Ties): each selected node of one object tied
// to the point of another object nearest it at the start, on a bar or a face.
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

struct Model;

// One attachment of an object, its nodes resolved to node ids (model_builder.cpp).
struct TieRequest {
  const ObjectDesc* object = nullptr;
  const AttachmentDesc* attachment = nullptr;
  std::vector<Index> nodes;
};

// A rigid tie's share of the structure's highest frequency bound: its spring oscillates at most
// at half of it (as contact between objects does, model/contact_builder.cpp), so central
// differences' step loses a little (the bound grows by at most a quarter where a tie sits) and the
// tie gives by its load over k, a small share of a bar's own stretch.
inline constexpr double kRigidTieFrequency = 0.5;

// Adds a tie for every node of every request: to the nearest point of the target's bars and faces,
// at that distance; a rigid tie's stiffness from the frequency bound of the model built so far
// (masses scaled, every spring in place). Throws a UserError at the attachment for a target that
// is no object, a tied node that is pinned, or a target with nothing to tie to.
void add_ties(const SceneDescription& scene, const std::vector<TieRequest>& requests, Model& model);

// 1 for each node a tie holds (`attach`), as a pin would: a piece of mesh so held is not free.
std::vector<std::uint8_t> tied_nodes(const Model& model);

}  // namespace dinam
