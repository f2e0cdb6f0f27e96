// A step's cost is estimated from what the model holds, not from a clock: the same scene gets the
// same estimate however busy the machine is, each kind counts its items, and threads shorten it
// only where the step shares its work.
#include "estimate/step_cost.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

Model cloth(int cells, const std::string& extra = "") {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
{1}
objects:
  - name: cloth
    mesh: {{grid: {{width: 1, height: 1, columns: {0}, rows: {0}, diagonals: one}}}}
    material: {{density: 1200, youngs_modulus: 2.0e7, radius: 0.001}}
)",
                                                       cells, extra)));
}

const StepCostPart* part(const StepCost& cost, const std::string& kind) {
  const auto found = std::find_if(cost.parts.begin(), cost.parts.end(),
                                  [&](const StepCostPart& p) { return p.kind == kind; });
  return found == cost.parts.end() ? nullptr : &*found;
}

TEST(StepCost, EachKindCountsItsItemsAndTheTotalIsTheirSum) {
  const Model model = cloth(40);
  const StepCost cost = estimate_step_cost(model, 1);
  ASSERT_NE(part(cost, "axial springs"), nullptr);
  EXPECT_EQ(part(cost, "axial springs")->items, model.bar_count());
  EXPECT_EQ(part(cost, "bending springs")->items, model.bend_count());
  EXPECT_EQ(part(cost, "nodes and integrator")->items, model.node_count());
  EXPECT_EQ(part(cost, "wind on faces"), nullptr);  // no wind: not counted
  double sum = 0.0;
  for (const StepCostPart& p : cost.parts) {
    EXPECT_GT(p.ns, 0.0) << p.kind;
    sum += p.ns;
  }
  EXPECT_DOUBLE_EQ(cost.serial_ns, sum);
  EXPECT_DOUBLE_EQ(cost.seconds, 1e-9 * sum);
  // The same model, the same answer: nothing here is measured.
  EXPECT_EQ(estimate_step_cost(model, 1).seconds, cost.seconds);
}

TEST(StepCost, WindAndGroundAddTheirItems) {
  const Model plain = cloth(20);
  const Model windy = cloth(20, "wind: {velocity: [5, 0, 0]}\nground: {height: -1}");
  const StepCost cost = estimate_step_cost(windy, 1);
  ASSERT_NE(part(cost, "wind on faces"), nullptr);
  EXPECT_EQ(part(cost, "wind on faces")->items, static_cast<double>(windy.wind.faces.size()));
  ASSERT_NE(part(cost, "ground"), nullptr);
  EXPECT_GT(cost.seconds, estimate_step_cost(plain, 1).seconds);
}

// Threads shorten a step only where it shares its work (kMinParallelItems springs): a large
// cloth at the efficiency bench_threads measures, a small one not at all.
TEST(StepCost, ThreadsShortenOnlyAStepLargeEnoughToShare) {
  const Model small = cloth(10);
  EXPECT_EQ(estimate_step_cost(small, 4).threads, 1);
  EXPECT_EQ(estimate_step_cost(small, 4).seconds, estimate_step_cost(small, 1).seconds);
  const Model large = cloth(60);
  const StepCost two = estimate_step_cost(large, 2);
  EXPECT_EQ(two.threads, 2);
  const double speedup = estimate_step_cost(large, 1).seconds / two.seconds;
  EXPECT_GT(speedup, 1.5);
  EXPECT_LT(speedup, 2.0);
}

// A cloth in contact with itself folds and lies on itself: its contact is counted at what that
// costs (bench_contact's sheets), far above watching for contact, and a second thread does not
// shorten it; contact with other objects alone is counted at watching's cost.
TEST(StepCost, ASurfaceInContactWithItselfCostsWhatLyingOnItselfDoes) {
  // The cloth and a pole beside it; the same cloth that also touches itself.
  const auto scene = [](const char* contact) {
    return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
contact: {}
objects:
  - name: cloth
    mesh: {{grid: {{width: 1, height: 1, columns: 60, rows: 60, diagonals: one}}}}
    material: {{density: 1200, youngs_modulus: 2.0e7, radius: 0.001}}
  - name: pole
    mesh: {{polyline: {{points: [[0.5, 0.5, -1], [0.5, 0.5, 0]], segments: 10}}}}
    material: {{density: 7850, youngs_modulus: 2.0e11, radius: 0.02}}
    pinned: {{all: true}}
)",
                                                         contact)));
  };
  const Model watching = scene("{objects: true}");
  const Model folding = scene("{objects: true, self: true}");
  const StepCost watching_cost = estimate_step_cost(watching, 1);
  const StepCostPart* watched = part(watching_cost, "contact between objects");
  ASSERT_NE(watched, nullptr);
  EXPECT_EQ(watched->items,
            static_cast<double>(watching.contact.bars.size() + watching.contact.points.size()));
  EXPECT_EQ(part(watching_cost, "a surface's contact with itself"), nullptr);
  const StepCost one = estimate_step_cost(folding, 1);
  const StepCostPart* pressed = part(one, "a surface's contact with itself");
  ASSERT_NE(pressed, nullptr);
  // The cloth's bars and nodes at the pressed cost, the pole's still watched.
  const Index cloth_nodes = 61 * 61;
  double cloth_items = 0;
  for (const Index b : folding.contact.bars) {
    cloth_items += folding.bar_nodes[2 * b] < cloth_nodes ? 1 : 0;
  }
  for (const Index p : folding.contact.points) {
    cloth_items += p < cloth_nodes ? 1 : 0;
  }
  EXPECT_GT(cloth_items, cloth_nodes);
  EXPECT_EQ(pressed->items, cloth_items);
  const StepCostPart* pole = part(one, "contact between objects");
  ASSERT_NE(pole, nullptr);
  EXPECT_EQ(pole->items + pressed->items,
            static_cast<double>(folding.contact.bars.size() + folding.contact.points.size()));
  EXPECT_GT(pressed->ns / pressed->items, 5.0 * watched->ns / watched->items);
  EXPECT_DOUBLE_EQ(one.unshared_ns, pressed->ns);
  // On two threads the rest of the step shares, the contact does not.
  const StepCost two = estimate_step_cost(folding, 2);
  ASSERT_EQ(two.threads, 2);
  EXPECT_GT(two.seconds, 1e-9 * pressed->ns);
  EXPECT_LT(two.seconds, one.seconds);
  const double speedup =
      estimate_step_cost(watching, 1).seconds / estimate_step_cost(watching, 2).seconds;
  EXPECT_NEAR(two.seconds - 1e-9 * pressed->ns, 1e-9 * (one.serial_ns - pressed->ns) / speedup,
              1e-12);
}

}  // namespace
}  // namespace dinam
