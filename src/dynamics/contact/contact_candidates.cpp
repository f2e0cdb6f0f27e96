#include "dynamics/contact/contact_candidates.hpp"

#include <algorithm>

#include "dynamics/contact/contact_closest.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// body(i) for every item in [0, count), each writing only data of its own: on the team when
// there are enough of them.
template <class Body>
void for_each_item(Index count, const Body& body) {
  thread_team().run(
      [&](const TeamMember& member) {
        const auto [first, last] = member.share(count, 8);
        for (Index i = first; i < last; ++i) {
          body(i);
        }
      },
      count < kMinParallelItems);
}

// Appends the pair to the candidates when its closest points are within reach + 2 skin.
void add_if_near(const ObjectContact& contact, double skin, const std::vector<Vec3>& x,
                 const ContactCandidate& pair, std::vector<ContactCandidate>& candidates) {
  if (closest_within(pair, x, contact_reach(contact, pair.key) + 2.0 * skin)) {
    candidates.push_back(pair);
  }
}

// The bars' and triangles' boxes grown by their radii and the skin, and the grids over them.
void file_boxes(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  ObjectContactWorkspace& work = state.object_contact;
  const std::vector<Vec3>& x = state.x;
  const double skin = work.skin;
  work.bar_boxes.resize(model.bar_count());
  work.bar_used.assign(model.bar_count(), 0);
  for_each_item(static_cast<Index>(contact.bars.size()), [&](Index k) {
    const Index b = contact.bars[k];
    if (!bar_broken(state, b)) {
      work.bar_boxes[b] = box_of(x[model.bar_nodes[2 * b]], x[model.bar_nodes[2 * b + 1]],
                                 contact.bar_radius[b] + skin);
      work.bar_used[b] = 1;
    }
  });
  const auto triangles = static_cast<Index>(contact.triangle_face.size());
  work.triangle_boxes.resize(triangles);
  work.triangle_used.assign(triangles, 0);
  for_each_item(triangles, [&](Index t) {
    if (!triangle_broken(contact, state, t)) {
      const Index* corners = &contact.triangles[3 * t];
      const double grow = contact.triangle_radius[t] + skin;
      Box box = box_of(x[corners[0]], x[corners[1]], grow);
      box.min = box.min.cwiseMin(x[corners[2]] - Vec3::Constant(grow));
      box.max = box.max.cwiseMax(x[corners[2]] + Vec3::Constant(grow));
      work.triangle_boxes[t] = box;
      work.triangle_used[t] = 1;
    }
  });
  double widest_point = 0.0;
  for (const Index p : contact.points) {
    widest_point = std::max(widest_point, 2.0 * (contact.point_radius[p] + skin));
  }
  work.bar_grid.build(work.bar_boxes, work.bar_used, 0.0);
  work.triangle_grid.build(work.triangle_boxes, work.triangle_used, widest_point);
}

// Which of two objects' bars look for the pairs between them: the object of fewer bars (of the
// lower id, where they have as many), so that a cloth over a pinned collider is searched from
// the collider's few bars, not each of the cloth's bars through its own neighbours.
bool bars_look_for(const Model& model, Index object, Index other) {
  const Index bars = model.objects[object].bar_count;
  const Index other_bars = model.objects[other].bar_count;
  return bars < other_bars || (bars == other_bars && object < other);
}

// Which objects' bars look for pairs at all (ObjectContactWorkspace::object_bars_look), once.
void note_looking_objects(const Model& model, ObjectContactWorkspace& work) {
  const auto objects = static_cast<Index>(model.objects.size());
  if (static_cast<Index>(work.object_bars_look.size()) == objects) {
    return;
  }
  work.object_bars_look.assign(static_cast<std::size_t>(objects), 0);
  for (Index a = 0; a < objects; ++a) {
    for (Index b = 0; b < objects; ++b) {
      if (objects_may_touch(model.contact, a, b) && (a == b || bars_look_for(model, a, b))) {
        work.object_bars_look[static_cast<std::size_t>(a)] = 1;
      }
    }
  }
}

// The narrowest skin, as a fraction of the widest (the largest contact radius).
constexpr double kNarrowestSkin = 0.05;

// What a search costs, in candidate checks (contact_candidates.hpp).
double search_cost(const ObjectContact& contact) {
  return kSearchCostInChecks * static_cast<double>(contact.bars.size() + contact.points.size());
}

// The candidate checks made since the last search: its candidates, every step since.
double checks_since_search(const State& state) {
  const ObjectContactWorkspace& work = state.object_contact;
  const auto steps = std::max<std::int64_t>(state.step - work.search_step, 1);
  return static_cast<double>(steps) * static_cast<double>(work.candidates.size());
}

// The skin for the next search (contact_candidates.hpp): narrower while checking the candidates
// since the last search cost more than a search, wider while it cost under a quarter of one.
double next_skin(const Model& model, const State& state) {
  const ObjectContact& contact = model.contact;
  const ObjectContactWorkspace& work = state.object_contact;
  if (!work.candidates_found) {
    return contact.skin;
  }
  const double checks = checks_since_search(state);
  const double search = search_cost(contact);
  if (checks > search) {
    return std::max(0.7 * work.skin, kNarrowestSkin * contact.skin);
  }
  if (checks < 0.25 * search) {
    return std::min(1.4 * work.skin, contact.skin);
  }
  return work.skin;
}

// Every pair within reach + 2 skin at the current positions.
void find_candidates(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  // Objects tied to each other (`attach`): their pairs that touch at the start where they are tied
  // are left out, as a mesh's neighbours are (model/tied_contact.hpp).
  const bool tied = model.ties.count() > 0;
  ObjectContactWorkspace& work = state.object_contact;
  const std::vector<Vec3>& x = state.x;
  work.skin = next_skin(model, state);
  const double skin = work.skin;
  file_boxes(model, state);
  note_looking_objects(model, work);
  work.candidates.clear();
  auto search = [&](Index count, const auto& gather) {
    gather_in_parallel(count, work.thread_candidates, work.candidates, gather);
  };
  // Each pair of bars is looked for from one of them: within an object from the lower id, between
  // two objects from the object whose bars look for the other's (bars_look_for); it is keyed
  // and laid out lower bar first either way.
  search(static_cast<Index>(contact.bars.size()), [&](Index k, auto& list) {
    const Index a = contact.bars[k];
    if (work.bar_used[a] == 0) {
      return;
    }
    const Index a0 = model.bar_nodes[2 * a];
    const Index a1 = model.bar_nodes[2 * a + 1];
    const Index object_a = model.node_object[a0];
    if (work.object_bars_look[object_a] == 0) {
      return;
    }
    const bool a_free = !model.pinned(a0) || !model.pinned(a1);
    work.bar_grid.visit_overlapping(work.bar_boxes[a], [&](Index b) {
      const Index b0 = model.bar_nodes[2 * b];
      const Index b1 = model.bar_nodes[2 * b + 1];
      const Index object_b = model.node_object[b0];
      const bool looked_for = object_a == object_b
                                  ? b > a && contact.object_self[object_a] != 0
                                  : objects_may_touch(contact, object_a, object_b) &&
                                        bars_look_for(model, object_a, object_b);
      if (!looked_for || a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1 ||
          (!a_free && model.pinned(b0) && model.pinned(b1)) ||
          (object_a == object_b && (contact.joined(a0, b0) || contact.joined(a0, b1) ||
                                    contact.joined(a1, b0) || contact.joined(a1, b1))) ||
          (tied && object_a != object_b && contact.tied_at_rest_bars(a, b))) {
        return;
      }
      const ContactCandidate pair =
          a < b ? ContactCandidate{pair_key(kBarBarContact, a, b), {a0, a1, b0, b1}}
                : ContactCandidate{pair_key(kBarBarContact, b, a), {b0, b1, a0, a1}};
      add_if_near(contact, skin, x, pair, list);
    });
  });
  search(static_cast<Index>(contact.points.size()), [&](Index k, auto& list) {
    const Index p = contact.points[k];
    const Box box = box_of(x[p], x[p], contact.point_radius[p] + skin);
    const Index object_p = model.node_object[p];
    work.triangle_grid.visit_overlapping(box, [&](Index t) {
      const Index* c = &contact.triangles[3 * t];
      if (p == c[0] || p == c[1] || p == c[2] ||
          !objects_may_touch(contact, object_p, model.node_object[c[0]]) ||
          (model.pinned(p) && model.pinned(c[0]) && model.pinned(c[1]) && model.pinned(c[2])) ||
          (object_p == model.node_object[c[0]] &&
           (contact.joined(p, c[0]) || contact.joined(p, c[1]) || contact.joined(p, c[2]))) ||
          (tied && object_p != model.node_object[c[0]] && contact.tied_at_rest_point(p, t))) {
        return;
      }
      add_if_near(contact, skin, x, {pair_key(kPointTriangleContact, p, t), {p, c[0], c[1], c[2]}},
                  list);
    });
  });
  work.reference_x = x;
  work.candidates_found = true;
  work.search_step = state.step;
  ++work.searches;
}

// True once some node of the contact has moved by more than the skin since the search.
bool moved_past_skin(const Model& model, const State& state) {
  const ObjectContactWorkspace& work = state.object_contact;
  const double skin_squared = work.skin * work.skin;
  for (const Index p : model.contact.points) {
    if ((state.x[p] - work.reference_x[p]).squaredNorm() > skin_squared) {
      return true;
    }
  }
  return false;
}

}  // namespace

void refresh_candidates(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  const ObjectContactWorkspace& work = state.object_contact;
  const bool costly = work.candidates_found && work.skin > kNarrowestSkin * contact.skin &&
                      checks_since_search(state) > search_cost(contact);
  if (!work.candidates_found || costly || moved_past_skin(model, state)) {
    find_candidates(model, state);
  }
}

void prepare_object_contact(const Model& model, State& state) {
  if (!model.contact.enabled) {
    return;
  }
  ObjectContactWorkspace& work = state.object_contact;
  const auto triangles = model.contact.triangle_face.size();
  work.bar_boxes.resize(static_cast<std::size_t>(model.bar_count()));
  work.bar_used.assign(static_cast<std::size_t>(model.bar_count()), 0);
  work.triangle_boxes.resize(triangles);
  work.triangle_used.assign(triangles, 0);
  work.reference_x.resize(static_cast<std::size_t>(model.node_count()));
  note_looking_objects(model, work);
}

}  // namespace dinam
