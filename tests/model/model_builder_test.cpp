#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "model/vertex_welding.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

TEST(VertexWelding, CoincidentVerticesBecomeOneNodeInFirstOccurrenceOrder) {
  const std::vector<Vec3> vertices = {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {1, 1e-9, 0}, {2, 0, 0}};
  const WeldResult weld = weld_vertices(vertices, weld_tolerance(vertices));
  EXPECT_EQ(weld.nodes.size(), 3u);
  EXPECT_EQ(weld.node_of_vertex, (std::vector<Index>{0, 1, 0, 1, 2}));
}

TEST(VertexWelding, PointsFartherThanTheToleranceStayApart) {
  // Tolerance 1e-6 of the 1 m diagonal: 1e-6 m. Points 1e-5 m apart are distinct bars' ends.
  const std::vector<Vec3> vertices = {{0, 0, 0}, {1e-5, 0, 0}, {1, 0, 0}};
  const WeldResult weld = weld_vertices(vertices, weld_tolerance(vertices));
  EXPECT_EQ(weld.nodes.size(), 3u);
}

TEST(VertexWelding, PointsWithinTheToleranceWeldWhereverTheyFallOnTheHashGrid) {
  // Pairs 0.9 tolerance apart in every direction, around points spread over many grid cells
  // (cells of two tolerances): each pair is one node, whichever cells its two points fall in.
  std::vector<Vec3> vertices = {{0, 0, 0}, {1, 1, 1}};  // a 1.7 m diagonal: tolerance 1.7e-6 m
  const double tolerance = weld_tolerance(vertices);
  const int pairs = 2000;
  for (int k = 0; k < pairs; ++k) {
    const double a = 0.37 * k;
    const Vec3 centre(0.1 + 0.8 * std::fmod(0.6180339887 * k, 1.0),
                      0.1 + 0.8 * std::fmod(0.41421356237 * k, 1.0),
                      0.1 + 0.8 * std::fmod(0.7320508075 * k, 1.0));
    const Vec3 direction(std::cos(a) * std::sin(1.3 * a), std::sin(a) * std::sin(1.3 * a),
                         std::cos(1.3 * a));
    vertices.push_back(centre);
    vertices.push_back(centre + 0.9 * tolerance * direction);
  }
  ASSERT_DOUBLE_EQ(weld_tolerance(vertices), tolerance);
  const WeldResult weld = weld_vertices(vertices, tolerance);
  EXPECT_EQ(weld.nodes.size(), static_cast<std::size_t>(2 + pairs));
  for (int k = 0; k < pairs; ++k) {
    EXPECT_EQ(weld.node_of_vertex[2 + 2 * k], weld.node_of_vertex[3 + 2 * k]) << k;
  }
}

TEST(VertexWelding, AVertexNearTwoKeptOnesJoinsTheEarlier) {
  // Nodes 0 and 1 are 1.5 tolerances apart (both kept); vertex 2 lies within the tolerance of
  // both and joins node 0, the earlier, whatever order the grid finds them in.
  const double t = 1e-6;
  for (const double x : {0.0, 0.3e-6, 0.7e-6, 1.1e-6, 1.9e-6}) {
    const std::vector<Vec3> vertices = {{x, 0, 0}, {x + 1.5 * t, 0, 0}, {x + 0.75 * t, 0, 0}};
    const WeldResult weld = weld_vertices(vertices, t);
    EXPECT_EQ(weld.node_of_vertex, (std::vector<Index>{0, 1, 0})) << x;
    const std::vector<Vec3> reversed = {{x + 1.5 * t, 0, 0}, {x, 0, 0}, {x + 0.75 * t, 0, 0}};
    EXPECT_EQ(weld_vertices(reversed, t).node_of_vertex, (std::vector<Index>{0, 1, 0})) << x;
  }
}

const char* const kTwoQuads = R"(version: 1
duration: 1
objects:
  - name: strip
    mesh: {grid: {width: 2, height: 1, columns: 2, rows: 1, diagonals: none}}
    material: {density: 2000, youngs_modulus: 3.0e6, area: 0.01}
    pinned: {indices: [0]}
    initial_velocity: [0, 0, 5]
)";

TEST(ModelBuilder, SharedEdgeIsOneBar) {
  // Two unit squares side by side share their middle edge: 6 nodes, 7 bars, not 8.
  const Model model = build_model(test::scene_from_yaml(kTwoQuads));
  EXPECT_EQ(model.node_count(), 6);
  EXPECT_EQ(model.bar_count(), 7);
  EXPECT_EQ(model.face_count(), 2);
}

// What no spring can use is not kept: yield limits and plastic sets of kinds that cannot yield,
// and per-bar damping without dampers (model.hpp); they are kept, full length, where they can.
TEST(ModelBuilder, KeepsYieldLimitsPlasticSetsAndDampingOnlyWhereTheyAct) {
  const Model elastic = build_model(test::scene_from_yaml(kTwoQuads));
  EXPECT_TRUE(elastic.bar_yield_force.empty());
  EXPECT_TRUE(elastic.bend_yield_moment.empty());
  EXPECT_TRUE(elastic.bar_damping.empty());
  EXPECT_EQ(yield_limit(elastic.bar_yield_force, 3), kNoYield);
  const State elastic_state = initial_state(elastic, 1e-4);
  EXPECT_TRUE(elastic_state.bar_plastic_set.empty());
  EXPECT_TRUE(elastic_state.bend_plastic_set.empty());

  std::string scene = kTwoQuads;
  scene.replace(scene.find("area: 0.01}"), 11,
                "area: 0.01, yield_stress: 2.0e5}\n    damping: {axial_ratio: 0.1}");
  const Model yielding = build_model(test::scene_from_yaml(scene));
  ASSERT_EQ(yielding.bar_yield_force.size(), static_cast<std::size_t>(yielding.bar_count()));
  EXPECT_DOUBLE_EQ(yield_limit(yielding.bar_yield_force, 3), 2.0e5 * 0.01);
  EXPECT_EQ(yielding.bar_damping.size(), static_cast<std::size_t>(yielding.bar_count()));
  EXPECT_GT(yielding.bar_damping[0], 0.0);
  const State yielding_state = initial_state(yielding, 1e-4);
  EXPECT_EQ(yielding_state.bar_plastic_set.size(), static_cast<std::size_t>(yielding.bar_count()));
  EXPECT_EQ(plastic_set_of(yielding_state.bar_plastic_set, 3), 0.0);
}

TEST(ModelBuilder, LumpsHalfOfEachBarOnEachEnd) {
  const Model model = build_model(test::scene_from_yaml(kTwoQuads));
  // ρ A = 2000 × 0.01 = 20 kg/m; 7 unit bars: 140 kg in all.
  EXPECT_NEAR(model.total_mass(), 140.0, 1e-12);
  // Corner node 0 ends two bars (10 kg each half); middle node 1 ends three.
  EXPECT_NEAR(model.node_mass[0], 20.0, 1e-12);
  EXPECT_NEAR(model.node_mass[1], 30.0, 1e-12);
  // k = EA / L0 = 3e6 × 0.01 / 1.
  for (const double k : model.bar_axial_stiffness) {
    EXPECT_NEAR(k, 3.0e4, 1e-9);
  }
}

TEST(ModelBuilder, PinnedNodesHaveNoInverseMassAndNoVelocity) {
  const Model model = build_model(test::scene_from_yaml(kTwoQuads));
  EXPECT_TRUE(model.pinned(0));
  EXPECT_EQ(model.node_initial_v[0], Vec3::Zero());
  for (Index i = 1; i < model.node_count(); ++i) {
    EXPECT_FALSE(model.pinned(i));
    EXPECT_EQ(model.node_initial_v[i], Vec3(0, 0, 5));
    EXPECT_DOUBLE_EQ(model.node_inv_mass[i], 1.0 / model.node_mass[i]);
  }
}

TEST(ModelBuilder, BoxPinsEveryNodeInside) {
  std::string scene = kTwoQuads;
  scene.replace(scene.find("{indices: [0]}"), 14,
                "{box: {min: [1.5, -1, -1], max: [3, 2, 1]}}");  // the column at x = 2
  const Model model = build_model(test::scene_from_yaml(scene));
  for (Index i = 0; i < model.node_count(); ++i) {
    EXPECT_EQ(model.pinned(i), model.node_initial_x[i].x() == 2.0) << i;
  }
}

TEST(ModelBuilder, VelocityGroupsOverrideTheObjectVelocity) {
  std::string scene = kTwoQuads;
  scene +=
      "    velocity_groups: [{nodes: {box: {min: [1.5, -1, -1], max: [3, 2, 1]}}, velocity: [1, 2, "
      "3]}]\n";
  const Model model = build_model(test::scene_from_yaml(scene));
  for (Index i = 1; i < model.node_count(); ++i) {
    const Vec3 expected = model.node_initial_x[i].x() == 2.0 ? Vec3(1, 2, 3) : Vec3(0, 0, 5);
    EXPECT_EQ(model.node_initial_v[i], expected) << i;
  }
}

TEST(ModelBuilder, BendingPairsAndTorsionReferences) {
  // A straight polyline of 4 bars: 3 collinear pairs by default, 0 torsion springs (no bar has a
  // reference that is not in line with it).
  const std::string line = R"(version: 1
duration: 1
objects:
  - mesh: {polyline: {points: [[0, 0, 0], [1, 0, 0]], segments: 4}}
    material: {density: 1, youngs_modulus: 1, radius: 0.1}
)";
  const Model chain = build_model(test::scene_from_yaml(line));
  EXPECT_EQ(chain.bend_count(), 3);
  EXPECT_EQ(chain.torsion_count(), 0);
  EXPECT_EQ(chain.bars_without_torsion, 4);
  // k = 2EI / (L1 + L2) with E = 1, I = π r⁴/4, L = 0.25.
  EXPECT_NEAR(chain.bend_stiffness[0], 2 * std::numbers::pi * 1e-4 / 4 / 0.5, 1e-15);
  EXPECT_NEAR(chain.bend_rest_angle[0], std::numbers::pi, 1e-12);

  // The cube's corners have three bars at right angles: `all` gives 3 pairs per corner, the
  // default one partner per bar (3 bars, 2 or 3 distinct pairs); each of the 12 edges has
  // perpendicular references at both ends. (`faces: net`: no corner springs of its quads'.)
  const std::string cube = R"(version: 1
duration: 1
objects:
  - mesh: {file: cube.obj}
    material: {density: 1, youngs_modulus: 1, radius: 0.1}
    bending_pairs: all
    faces: net
)";
  const Model all = build_model(test::scene_from_yaml(cube));
  EXPECT_EQ(all.bend_count(), 8 * 3);
  EXPECT_EQ(all.torsion_count(), 12);
  // Both references of an edge lie along the cube's other axes: the rest twist is 0 or ±π/2.
  for (Index s = 0; s < all.torsion_count(); ++s) {
    const double quarter_turns = all.torsion_rest_angle[s] / (std::numbers::pi / 2);
    EXPECT_NEAR(quarter_turns, std::round(quarter_turns), 1e-6);
  }
}

// banner.obj (tests/data) with its rope lines in another material, chosen by the file's material
// name or by its group: the two 0.5 m rope bars take the rope's EA/L and mass, the cloth's four
// sides and diagonal keep the object's. A later part wins over an earlier one.
TEST(ModelBuilder, PartsByTheMeshFilesMaterialsAndGroups) {
  const double cloth_area = 1e-4;
  const double rope_area = 4e-4;
  auto banner = [](const std::string& parts) {
    return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
ground: {{contact: false}}  # the banner hangs below z = 0; only its parts are looked at
objects:
  - mesh: {{file: banner.obj}}
    material: {{density: 1000, youngs_modulus: 1.0e6, area: 1.0e-4}}
    parts:
{})",
                                                         parts)));
  };
  const std::string rope_material =
      "material: {density: 1500, youngs_modulus: 3.0e6, area: 4.0e-4}";
  for (const std::string selector : {"mesh_material: rope", "mesh_group: ropes"}) {
    const Model model = banner(fmt::format("      - {{{}, {}}}\n", selector, rope_material));
    ASSERT_EQ(model.bar_count(), 7);
    int rope_bars = 0;
    for (Index b = 0; b < model.bar_count(); ++b) {
      const double length = model.bar_rest_length[b];
      const bool rope = std::abs(length - 0.5) < 1e-12;  // only the rope's bars are 0.5 m
      rope_bars += rope ? 1 : 0;
      EXPECT_DOUBLE_EQ(model.bar_axial_stiffness[b],
                       rope ? 3.0e6 * rope_area / length : 1.0e6 * cloth_area / length)
          << selector << ", bar " << b;
    }
    EXPECT_EQ(rope_bars, 2) << selector;
    EXPECT_NEAR(model.total_mass(),
                1000 * cloth_area * (4.0 + std::sqrt(2.0)) + 1500 * rope_area * 1.0, 1e-15)
        << selector;
  }
  // The cloth in the rope's material, then its bottom side back in the object's by a later part.
  const Model later = banner(fmt::format(
      "      - {{mesh_group: cloth, {}}}\n"
      "      - {{nodes: {{box: {{min: [-1, -1, -1], max: [2, 1, 0.5]}}}}, material: {{density: "
      "1000, youngs_modulus: 1.0e6, area: 1.0e-4}}}}\n",
      rope_material));
  // In the box: the bottom side (the tail is the object's anyway); the hanger was never a part's.
  EXPECT_NEAR(later.total_mass(),
              1500 * rope_area * (3.0 + std::sqrt(2.0)) + 1000 * cloth_area * (1.0 + 0.5 + 0.5),
              1e-15);
}

TEST(ModelBuilder, ObjectsGetContiguousRanges) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - name: a
    mesh: {file: cube.obj}
    material: {density: 1, youngs_modulus: 1, radius: 0.1}
  - name: b
    mesh: {file: rope.obj}
    material: {density: 1, youngs_modulus: 1, radius: 0.1}
)"));
  ASSERT_EQ(model.objects.size(), 2u);
  EXPECT_EQ(model.objects[1].first_node, 8);
  EXPECT_EQ(model.objects[1].first_bar, 12);
  for (Index b = 12; b < model.bar_count(); ++b) {
    EXPECT_EQ(model.node_object[model.bar_nodes[2 * b]], 1);
    EXPECT_EQ(model.node_object[model.bar_nodes[2 * b + 1]], 1);
  }
}

}  // namespace
}  // namespace dinam

namespace dinam {
namespace {

// Built from typed values, a material may skip the scene reader's ranges; the model still refuses
// to hand a step masses or stiffnesses it cannot compute with, naming the object.
TEST(ModelBuilder, DerivedQuantitiesBeyondDoublePrecisionAreRefused) {
  SceneDescription scene = test::scene_from_yaml(
      "version: 1\nduration: 1\nobjects:\n  - name: rope\n    mesh: {file: rope.obj}\n    "
      "material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}\n");
  EXPECT_NO_THROW(build_model(scene));
  scene.objects[0].material.density = 1e308;  // ρ A L: 1e308 × 3e-4 × L is finite, ½ of it too
  scene.objects[0].material.area = 1e10;      // … but not with this area
  test::expect_user_error([&] { build_model(scene); }, 6,
                          {"object 'rope'", "which no step can use"});
  scene.objects[0].material.density = 1000.0;
  scene.objects[0].material.area = 3e-4;
  scene.objects[0].material.youngs_modulus = 1e308;
  scene.objects[0].material.area_moment = 1e300;
  test::expect_user_error(
      [&] { build_model(scene); }, 6,
      {"a stiffness of the model's bending springs is inf", "beyond double precision"});
}

// `radius: 1` where millimetres were meant: the cloth's wires are thicker than its bars are
// long, and weigh tonnes. A warning names the material's line, the mass and the unit; the same
// cloth at 1 mm gets none.
TEST(ModelBuilder, AWireRadiusLargerThanItsBarsIsWarnedOf) {
  const std::string scene = R"(version: 1
duration: 1
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 20, rows: 20}, translation: [0, 0, 1]}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: RADIUS}
)";
  auto with_radius = [&](const std::string& radius) {
    std::string text = scene;
    text.replace(text.find("RADIUS"), 6, radius);
    return build_model(test::scene_from_yaml(text));
  };
  const Model slip = with_radius("1");
  ASSERT_EQ(slip.warnings.size(), 1U);
  test::expect_contains(slip.warnings[0],
                        {":6:15: warning: object 'cloth'",
                         "wire radius, 1 m, is larger than its bars", "'radius' is in metres"});
  // 840 bars of 0.05 m and 400 diagonals of 0.07 m, each π·1²·L·1000 kg: 221 t.
  EXPECT_GT(slip.total_mass(), 1e5);
  EXPECT_TRUE(with_radius("0.001").warnings.empty());
}

// A mesh file modelled in centimetres and read as metres: a cloth 100 times too large (the banner,
// 1 m across, `scale: 100`) or a rope (1 m, `scale: 2000`) is warned of at its mesh with its
// size, its mass and `units`; the same at a size things are made, or a generated grid that large
// (metres by construction), is not.
TEST(ModelBuilder, AMeshFileFarLargerThanItsKindIsMadeSuggestsUnits) {
  auto scene_of = [](const std::string& mesh, const std::string& material) {
    return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
objects:
  - name: thing
    mesh: {}
    material: {}
)",
                                                         mesh, material)));
  };
  // Of the warnings (a coarse cotton mesh gets others), the one on its size.
  auto size_warnings = [](const Model& model) {
    std::vector<std::string> found;
    std::copy_if(model.warnings.begin(), model.warnings.end(), std::back_inserter(found),
                 [](const std::string& w) { return w.find("is made (") != std::string::npos; });
    return found;
  };
  const std::string cotton = "{preset: cotton}";
  const std::vector<std::string> curtain =
      size_warnings(scene_of("{file: textured_quad.obj, scale: 100}", cotton));
  ASSERT_EQ(curtain.size(), 1U);
  test::expect_contains(curtain[0], {":5:11: warning: object 'thing'", "m across and weighs",
                                     "larger than any cloth is made (50 m)", "'units: cm'"});
  EXPECT_TRUE(size_warnings(scene_of("{file: textured_quad.obj}", cotton)).empty());
  EXPECT_TRUE(
      size_warnings(scene_of("{grid: {width: 80, height: 80, columns: 4, rows: 4}}", cotton))
          .empty());
  const std::string hemp = "{density: 1000, youngs_modulus: 1.0e9, radius: 0.008}";
  const std::vector<std::string> rope =
      size_warnings(scene_of("{file: rope.obj, scale: 2000}", hemp));
  ASSERT_EQ(rope.size(), 1U);
  test::expect_contains(rope[0], {"2000 m across", "any rope or cable", "'units: cm'"});
  EXPECT_TRUE(size_warnings(scene_of("{file: rope.obj, scale: 900}", hemp)).empty());
}

// A mesh of three pieces that share no vertex (a square, a triangle beside its corner, a loose
// segment: tests/data/pieces.obj) is three structures: a note at the mesh says how many, how
// large the largest, and how many no pin holds; none where every piece holds a pinned node.
TEST(ModelBuilder, AMeshOfSeparatePiecesIsNotedAtItsMesh) {
  auto with_pins = [](const std::string& pins) {
    return build_model(test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - name: body
    mesh: {file: pieces.obj}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.001}
)" + pins));
  };
  const Model loose = with_pins("");
  ASSERT_EQ(loose.warnings.size(), 1U);
  test::expect_contains(loose.warnings[0],
                        {":5:11: note: object 'body': its mesh is 3 separate pieces",
                         "the largest has 4 of its 9 nodes", "3 of them held by no pin",
                         "contact: {objects: true, self: true}"});
  const Model body_pinned = with_pins("    pinned: {indices: [0]}\n");
  ASSERT_EQ(body_pinned.warnings.size(), 1U);
  test::expect_contains(body_pinned.warnings[0], {"2 of them held by no pin"});
  EXPECT_TRUE(with_pins("    pinned: {indices: [0, 4, 7]}\n").warnings.empty());
}

// A collider (`role: collider`) needs no material and is held whole; an object pinned whole gets
// no material's warnings: the same coarse triangle mesh with a 1 m wire radius, as a cotton sheet
// free to move, is warned of twice (its lattice triangles, its radius); as a collider, or pinned
// by a box around all of it, not at all. `pinned` beside a collider and an unknown role are
// refused at their lines.
TEST(ModelBuilder, AColliderNeedsNoMaterialAndIsWarnedOfNothingAMaterialDecides) {
  auto model_of = [](const std::string& object) {
    return build_model(test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - name: body
    mesh: {grid: {width: 1, height: 1, columns: 3, rows: 3}}
)" + object));
  };
  const Model free = model_of("    material: {preset: cotton}\n    pinned: {indices: [0]}\n");
  EXPECT_GE(free.warnings.size(), 1U);
  const Model collider = model_of("    role: collider\n");
  EXPECT_TRUE(collider.warnings.empty()) << collider.warnings[0];
  for (Index i = 0; i < collider.node_count(); ++i) {
    EXPECT_TRUE(collider.pinned(i)) << i;
  }
  // Its shell is its contact radius, else 5 mm.
  EXPECT_DOUBLE_EQ(collider.objects[0].wire_radius, kColliderShell);
  EXPECT_DOUBLE_EQ(
      model_of("    role: collider\n    contact: {radius: 0.02}\n").objects[0].wire_radius, 0.02);
  const Model wide = model_of("    material: {density: 1000, youngs_modulus: 1e6, radius: 1}\n");
  ASSERT_EQ(wide.warnings.size(), 1U);
  EXPECT_TRUE(model_of("    material: {density: 1000, youngs_modulus: 1e6, radius: 1}\n"
                       "    pinned: {box: {min: [-1, -1, -1], max: [2, 2, 1]}}\n")
                  .warnings.empty());
  EXPECT_TRUE(
      model_of("    material: {preset: cotton}\n    pinned: {all: true}\n").warnings.empty());
  test::expect_user_error([&] { model_of("    role: collider\n    pinned: {all: true}\n"); }, 7,
                          {"object 'body' is a collider, held whole", "leave 'pinned' out"});
  test::expect_user_error([&] { model_of("    role: obstacle\n"); }, 6,
                          {"must be flexible", "or collider", "got 'obstacle'"});
  test::expect_user_error([&] { model_of("    pinned: {all: true}\n"); }, 4, {"material"});
}

}  // namespace
}  // namespace dinam
