#include "model/contact_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string_view>

#include "core/error.hpp"
#include "model/frequency_bound.hpp"
#include "model/tied_contact.hpp"

namespace dinam {

namespace {

// A penalty may be stiffer than the structure, but not so much stiffer that it alone sets a step
// hundreds of times shorter than the structure's own: that is a unit slip (N/mm for N/m), and
// `timestep: auto` would make the run last days without a word.
constexpr double kStiffestPenaltyFrequencyRatio = 100.0;

// The automatic contact frequencies, as shares of the structure's highest: of the ground, and of
// contact between objects (stiffer, for its speed envelope; its penalty is softer near the
// surface, where a bounce needs it resolved: object_contact.cpp).
constexpr double kGroundContactFrequency = 0.125;
constexpr double kObjectContactFrequency = 0.5;
// `inv_mass` is what the penalty's oscillation sees on the lightest contact: 1/m against the
// ground, 1/m + 1/m for two nodes pressed together (ω² = k · inv_mass). `structure` is the
// structure's highest ω² bound.
void check_penalty_stiffness(const FileLoc& loc, std::string_view what, double stiffness,
                             double inv_mass, double structure) {
  if (structure <= 0.0 || inv_mass <= 0.0) {
    return;  // a structure without springs, or all pinned: nothing to compare with
  }
  const double ratio = std::sqrt(stiffness * inv_mass / structure);
  if (ratio > kStiffestPenaltyFrequencyRatio) {
    const double largest =
        kStiffestPenaltyFrequencyRatio * kStiffestPenaltyFrequencyRatio * structure / inv_mass;
    throw_user_error(loc,
                     "a {} stiffness of {:g} N/m makes the lightest nodes' contacts oscillate "
                     "{:.0f} times faster than the structure's highest frequency, so every step "
                     "would be that much shorter; give at most {:.3g} N/m (in N/m, not N/mm), "
                     "or 'auto'",
                     what, stiffness, ratio, largest);
  }
}

// Nodes that start this far below the ground, or more, are a mesh placed in the ground (its
// units, an up axis that is y, a translation that was meant upwards): the penalty would launch it
// with energy nothing in the scene supplied. A hair below (a mesh modelled lying on z = 0, its
// rounding) is allowed.
constexpr double kLeastSunkDepth = 1e-3;   // m
constexpr double kSunkShareOfSize = 1e-3;  // of the model's size, for large models

void refuse_start_below_ground(const SceneDescription& scene, const Model& model) {
  const GroundContact& ground = model.ground;
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = -low;
  Index deepest = -1;
  double depth = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    const Vec3& x = model.node_initial_x[i];
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
    const double below = (ground.point - x).dot(ground.normal);
    if (!model.pinned(i) && below > depth) {
      depth = below;
      deepest = i;
    }
  }
  const double size = model.node_count() > 0 ? (high - low).norm() : 0.0;
  if (deepest < 0 || depth <= std::max(kLeastSunkDepth, kSunkShareOfSize * size)) {
    return;
  }
  const Index o = model.node_object[deepest];
  const ModelObject& object = model.objects[o];
  throw_user_error(scene.objects[o].loc,
                   "'{}' starts {:.3g} m below the ground (node {} of its mesh), and the ground "
                   "would launch it with energy from nowhere; move it up (its mesh's "
                   "'translation'), check the mesh's units and up axis, or lower the ground "
                   "('ground.height')",
                   object.name, depth, deepest - object.first_node);
}

// A bar's contact radius: its object's, else its wire radius.
double bar_contact_radius(const SceneDescription& scene, const Model& model, Index bar) {
  const Index object = model.node_object[model.bar_nodes[2 * bar]];
  return scene.objects[object].contact.radius.value_or(model.bar_radius[bar]);
}

// Where each node meets the ground: at its contact radius, the largest of its bars', but never
// below where it starts. A node modelled nearer the plane than its radius (a cloth laid on z = 0)
// meets it where it lies, instead of being thrown off by a penalty it was placed inside of.
std::vector<double> ground_contact_radius(const SceneDescription& scene, const Model& model) {
  const GroundContact& ground = model.ground;
  std::vector<double> radius(model.node_count(), 0.0);
  for (Index b = 0; b < model.bar_count(); ++b) {
    for (const Index n : {model.bar_nodes[2 * b], model.bar_nodes[2 * b + 1]}) {
      radius[n] = std::max(radius[n], bar_contact_radius(scene, model, b));
    }
  }
  for (Index i = 0; i < model.node_count(); ++i) {
    const double height = (model.node_initial_x[i] - ground.point).dot(ground.normal);
    radius[i] = std::clamp(height, 0.0, radius[i]);
  }
  return radius;
}

double largest_inv_mass(const Model& model, std::span<const Index> nodes) {
  double largest = 0.0;
  for (const Index i : nodes) {
    largest = std::max(largest, model.node_inv_mass[i]);
  }
  return largest;
}

// Each node's penalty k = stiffness(m) and its damper 2 ζ √(k m).
template <class Stiffness>
void set_ground_penalty(Model& model, double damping_ratio, const Stiffness& stiffness) {
  GroundContact& ground = model.ground;
  ground.damping_ratio = damping_ratio;
  ground.node_stiffness.resize(model.node_count());
  ground.node_damping.resize(model.node_count());
  for (Index i = 0; i < model.node_count(); ++i) {
    const double m = model.node_mass[i];
    const double k = stiffness(m);
    ground.node_stiffness[i] = k;
    ground.node_damping[i] = 2.0 * damping_ratio * std::sqrt(k * m);
  }
}

}  // namespace

void add_ground_contact(const SceneDescription& scene, Model& model) {
  const GroundDesc& desc = scene.ground;
  GroundContact& ground = model.ground;
  ground.enabled = desc.contact;
  ground.point = desc.point;
  ground.normal = desc.normal;
  ground.static_friction = desc.static_friction;
  ground.kinetic_friction = desc.kinetic_friction;
  ground.stick = desc.stick;
  if (!ground.enabled) {
    return;
  }
  refuse_start_below_ground(scene, model);
  ground.node_radius = ground_contact_radius(scene, model);
  // Auto: every node gets the same contact frequency ω_c = ω_max / 8 of the structure: at the
  // automatic step (ω_max Δt ≤ 1.6) ω_c Δt ≤ 0.2, an impact lasts some 16 steps, and the rebound
  // keeps the spring–dashpot's restitution to 2 % (ground_contact.hpp). The ground then costs
  // the step about 1 %, and an impact at speed v penetrates about v / ω_c.
  const double structure = max_frequency_squared_bound(model, false);
  if (desc.stiffness) {
    const double lightest_inv_mass =
        model.node_inv_mass.empty() ? 0.0 : std::ranges::max(model.node_inv_mass);
    check_penalty_stiffness(desc.stiffness_loc, "ground", *desc.stiffness, lightest_inv_mass,
                            structure);
    set_ground_penalty(model, desc.damping_ratio, [&](double) { return *desc.stiffness; });
  } else {
    const double omega_squared =
        structure > 0.0 ? kGroundContactFrequency * kGroundContactFrequency * structure : 1e4;
    ground.automatic_frequency_squared = omega_squared;
    set_ground_penalty(model, desc.damping_ratio, [&](double m) { return m * omega_squared; });
  }
}

void soften_ground(Model& model, double frequency) {
  GroundContact& ground = model.ground;
  if (!ground.enabled || !ground.automatic_frequency_squared) {
    return;  // a stiffness the scene gives is the user's to keep
  }
  const double omega_squared = std::min(*ground.automatic_frequency_squared, frequency * frequency);
  ground.automatic_frequency_squared = omega_squared;
  set_ground_penalty(model, ground.damping_ratio, [&](double m) { return m * omega_squared; });
}

void add_object_contact(const SceneDescription& scene, Model& model) {
  ObjectContact& contact = model.contact;
  const ContactDesc& desc = scene.contact;
  const auto objects = static_cast<Index>(model.objects.size());
  contact.object_between.assign(objects, 0);
  contact.object_self.assign(objects, 0);
  Index between = 0;
  for (Index o = 0; o < objects; ++o) {
    const ObjectContactDesc& own = scene.objects[o].contact;
    contact.object_between[o] = own.objects.value_or(desc.objects) ? 1 : 0;
    contact.object_self[o] = own.self.value_or(desc.self) ? 1 : 0;
    between += contact.object_between[o];
  }
  auto takes_part = [&](Index object) {
    return contact.object_self[object] != 0 || (between > 1 && contact.object_between[object] != 0);
  };
  contact.enabled = false;
  for (Index o = 0; o < objects; ++o) {
    contact.enabled = contact.enabled || takes_part(o);
  }
  if (!contact.enabled) {
    contact = ObjectContact{};
    return;
  }

  // Radii: the object's, else each bar's wire radius; a node takes the largest of its bars', a
  // triangle the smallest of its corners'.
  contact.bar_radius.assign(model.bar_count(), 0.0);
  contact.point_radius.assign(model.node_count(), 0.0);
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index object = model.node_object[n0];
    if (!takes_part(object)) {
      continue;
    }
    const double radius = bar_contact_radius(scene, model, b);
    contact.bars.push_back(b);
    contact.bar_radius[b] = radius;
    for (const Index n : {n0, model.bar_nodes[2 * b + 1]}) {
      contact.point_radius[n] = std::max(contact.point_radius[n], radius);
    }
  }
  for (Index n = 0; n < model.node_count(); ++n) {
    if (contact.point_radius[n] > 0.0) {
      contact.points.push_back(n);
    }
  }
  // Faces fan into triangles from their first corner (a quad gives two). An object drawn as
  // wires (a net of cords, whose faces are the holes between them) has none unless it asks.
  auto faces_take_part = [&](Index object) {
    const ObjectDesc& object_desc = scene.objects[object];
    return takes_part(object) &&
           object_desc.contact.faces.value_or(object_desc.style != DrawStyle::kWire);
  };
  for (Index f = 0; f < model.face_count(); ++f) {
    const Index first = model.face_offsets[f];
    const Index size = model.face_offsets[f + 1] - first;
    const Index* corners = &model.face_nodes[first];
    if (!faces_take_part(model.node_object[corners[0]])) {
      continue;
    }
    for (Index k = 1; k + 1 < size; ++k) {
      contact.triangles.insert(contact.triangles.end(), {corners[0], corners[k], corners[k + 1]});
      contact.triangle_face.push_back(f);
      contact.triangle_radius.push_back(
          std::min({contact.point_radius[corners[0]], contact.point_radius[corners[k]],
                    contact.point_radius[corners[k + 1]]}));
    }
  }

  // Each node's neighbours along bars of the contact, as a sorted list per node.
  std::vector<std::vector<Index>> joined(model.node_count());
  for (const Index b : contact.bars) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    joined[n0].push_back(n1);
    joined[n1].push_back(n0);
  }
  contact.neighbour_offsets.assign(1, 0);
  for (std::vector<Index>& list : joined) {
    std::sort(list.begin(), list.end());
    contact.neighbours.insert(contact.neighbours.end(), list.begin(), list.end());
    contact.neighbour_offsets.push_back(static_cast<Index>(contact.neighbours.size()));
  }

  leave_out_pairs_tied_at_rest(model);

  // The skin of the candidate pairs: the largest radius. Wider, the pairs are found less often
  // but more of them are checked every step.
  contact.skin = *std::max_element(contact.bar_radius.begin(), contact.bar_radius.end());

  // Auto: every contact oscillates at most at half the structure's highest frequency bound, as
  // the ground's nodes do; the step's bound then counts two contacts on every node.
  const double structure = max_frequency_squared_bound(model, false);
  if (desc.stiffness) {
    contact.stiffness = *desc.stiffness;
    check_penalty_stiffness(desc.stiffness_loc, "contact", contact.stiffness,
                            2.0 * largest_inv_mass(model, contact.points), structure);
  } else {
    contact.omega_squared =
        structure > 0.0 ? kObjectContactFrequency * kObjectContactFrequency * structure : 1e4;
  }
  contact.damping_ratio = desc.damping_ratio;
  contact.static_friction = desc.static_friction;
  contact.kinetic_friction = desc.kinetic_friction;
}

}  // namespace dinam
