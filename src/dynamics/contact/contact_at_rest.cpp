#include "dynamics/contact/contact_at_rest.hpp"

#include "dynamics/contact/contact_pairs.hpp"
#include "dynamics/pin_motion.hpp"
#include "dynamics/state.hpp"
#include "dynamics/tearing.hpp"
#include "model/model.hpp"

namespace dinam {

std::optional<RestOverlap> contact_overlap_at_rest(const Model& model, double tolerance) {
  if (!model.contact.enabled) {
    return std::nullopt;
  }
  State state;
  state.x = model.node_initial_x;
  prepare_tearing(model, state);
  place_driven_nodes(model, 0.0, state);
  find_touching_pairs(model, state);
  std::optional<RestOverlap> deepest;
  Index pairs = 0;
  for (const ContactPoint& point : state.object_contact.touching) {
    const double reach = contact_reach(model.contact, point.key);
    const double distance = point.separation.norm();
    if (distance >= (1.0 - tolerance) * reach) {
      continue;
    }
    ++pairs;
    if (!deepest || reach - distance > deepest->reach - deepest->distance) {
      deepest = RestOverlap{
          0,        point.key, model.node_object[point.nodes[0]], model.node_object[point.nodes[3]],
          distance, reach};
    }
  }
  if (deepest) {
    deepest->pairs = pairs;
  }
  return deepest;
}

}  // namespace dinam
