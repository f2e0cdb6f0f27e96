// Whether a free piece comes to rest where it lands (solver/landing_balance.hpp), checked on solids
// whose landing is known in closed form: a closed cylinder of s sides on its side stands on the
// line of its lowest side, its centre of mass straight above it (tips at 0°), and rolls onto the
// next side after turning 180°/s; on its end it stands unless tilted past atan(apothem over half
// its length), and its next face is its side, 90° away; a cube on a face tips at 45° onto the next
// face at 90°, and on an edge tips at once onto a face 45° away, where it lies still.
#include "solver/landing_balance.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "model/mesh_pieces.hpp"
#include "model/model.hpp"
#include "estimate/implicit_cost.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

constexpr double kPi = std::numbers::pi;
// Degrees: meshes are read in single precision (assimp), a relative 6e-8 of each coordinate.
constexpr double kAngle = 1e-5;

double degrees(double radians) {
  return radians * 180.0 / kPi;
}

class LandingBalance : public ::testing::Test {
 protected:
  // A closed cylinder of `sides` sides, radius 0.1 m and length 0.4 m, triangulated (its ends fans
  // about a centre node): lying along x with a side's line lowest, or standing along z.
  std::string cylinder(int sides, bool standing) const {
    const double r = 0.1;
    const double half = 0.2;
    std::string obj;
    const auto vertex = [&](double axial, double u, double v) {
      obj += standing ? fmt::format("v {} {} {}\n", u, v, axial)
                      : fmt::format("v {} {} {}\n", axial, u, v);
    };
    for (const double axial : {-half, half}) {
      for (int k = 0; k < sides; ++k) {
        const double angle = -kPi / 2.0 + 2.0 * kPi * k / sides;  // k = 0 lowest when lying
        vertex(axial, r * std::cos(angle), r * std::sin(angle));
      }
    }
    vertex(-half, 0.0, 0.0);  // the ends' centres: nodes 2s + 1 and 2s + 2
    vertex(half, 0.0, 0.0);
    for (int k = 0; k < sides; ++k) {
      const int a = k + 1;
      const int b = (k + 1) % sides + 1;
      obj += fmt::format("f {} {} {}\nf {} {} {}\n", a, b, b + sides, a, b + sides, a + sides);
      obj += fmt::format("f {} {} {}\nf {} {} {}\n", 2 * sides + 1, b, a, 2 * sides + 2, a + sides,
                         b + sides);
    }
    return write("cylinder.obj", obj);
  }

  // A unit cube of triangles, turned by `turn` radians about x (π/4: on an edge).
  std::string cube(double turn) const {
    std::string obj;
    for (int v = 0; v < 8; ++v) {
      const double x = (v & 1) != 0 ? 0.5 : -0.5;
      const double y = (v & 2) != 0 ? 0.5 : -0.5;
      const double z = (v & 4) != 0 ? 0.5 : -0.5;
      obj += fmt::format("v {} {} {}\n", x, y * std::cos(turn) - z * std::sin(turn),
                         y * std::sin(turn) + z * std::cos(turn));
    }
    // Each face as two triangles (1-based corners, the bits of x, y and z).
    obj +=
        "f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\n"
        "f 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\n";
    return write("cube.obj", obj);
  }

  // The model of the mesh file dropped from 1 m over the ground.
  static Model dropped(const std::string& file) {
    return build_model(test::scene_from_yaml(
        fmt::format("version: 1\nduration: 1\nintegrator: implicit\nobjects:\n"
                    "  - mesh: {{file: \"{}\", translation: [0, 0, 1]}}\n"
                    "    material: {{density: 1000, youngs_modulus: 1.0e7, radius: 0.005}}\n",
                    file)));
  }

  static PieceLanding only_landing(const Model& model) {
    const std::vector<PieceLanding> landings = piece_landings(model, mesh_pieces(model));
    EXPECT_EQ(landings.size(), 1u);
    return landings.empty() ? PieceLanding{} : landings.front();
  }

 private:
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path path = folder_.path() / name;
    std::ofstream(path) << text;
    return path.string();
  }

  test::TemporaryFolder folder_{"landing"};
};

// On its side, a log rolls: at its balance point and a round base, 180°/16 = 11.25° to its next
// side. The estimate takes it for a structure that rocks, naming a node of its lowest line.
TEST_F(LandingBalance, ALogOnItsSideRollsFromSideToSide) {
  const int sides = 16;
  const Model model = dropped(cylinder(sides, false));
  const PieceLanding landing = only_landing(model);
  EXPECT_NEAR(landing.tipping_degrees, 0.0, kAngle);
  EXPECT_NEAR(landing.next_face_degrees, 180.0 / sides, kAngle);
  EXPECT_TRUE(landing.node == 0 || landing.node == sides) << landing.node;
  ASSERT_TRUE(rocking_landing(model, mesh_pieces(model)).has_value());
  EXPECT_EQ(bars_free_share(model), 0.0);  // a closed surface of triangles
  EXPECT_EQ(expected_motion(model), ImplicitMotion::kRocks);
}

// On its end, the same log stands: its centre of mass over the middle of a 16-gon of apothem
// r cos(π/16), half its length up, tips at atan(r cos(π/16) / (L/2)) = 26.1°, onto its side.
TEST_F(LandingBalance, ALogOnItsEndStands) {
  const int sides = 16;
  const Model model = dropped(cylinder(sides, true));
  const PieceLanding landing = only_landing(model);
  EXPECT_NEAR(landing.tipping_degrees, degrees(std::atan2(0.1 * std::cos(kPi / sides), 0.2)),
              kAngle);
  EXPECT_NEAR(landing.next_face_degrees, 90.0, kAngle);
  EXPECT_FALSE(rocking_landing(model, mesh_pieces(model)).has_value());
  EXPECT_EQ(expected_motion(model), ImplicitMotion::kHoldsItsShape);
}

// A cube on a face tips at 45° and turns 90° onto the next; on an edge it is at its balance point
// and turns 45° onto a face, where it lies still: it topples once, it does not roll.
TEST_F(LandingBalance, ACubeOnAnEdgeTopplesOnceAndLiesStill) {
  const Model flat = dropped(cube(0.0));
  const PieceLanding on_face = only_landing(flat);
  EXPECT_NEAR(on_face.tipping_degrees, 45.0, kAngle);
  EXPECT_NEAR(on_face.next_face_degrees, 90.0, kAngle);
  const Model turned = dropped(cube(kPi / 4.0));
  const PieceLanding on_edge = only_landing(turned);
  EXPECT_NEAR(on_edge.tipping_degrees, 0.0, kAngle);
  EXPECT_NEAR(on_edge.next_face_degrees, 45.0, kAngle);
  EXPECT_FALSE(rocking_landing(turned, mesh_pieces(turned)).has_value());
  EXPECT_EQ(expected_motion(turned), ImplicitMotion::kHoldsItsShape);
}

// A piece held by a pin does not land, and without a ground nothing does.
TEST_F(LandingBalance, OnlyFreePiecesLandAndOnlyOnAGround) {
  const std::string log = cylinder(16, false);
  const Model pinned = build_model(test::scene_from_yaml(
      fmt::format("version: 1\nduration: 1\nobjects:\n"
                  "  - mesh: {{file: \"{}\", translation: [0, 0, 1]}}\n"
                  "    material: {{density: 1000, youngs_modulus: 1.0e7, radius: 0.005}}\n"
                  "    pinned: {{indices: [0]}}\n",
                  log)));
  EXPECT_TRUE(piece_landings(pinned, mesh_pieces(pinned)).empty());
  const Model no_ground = build_model(test::scene_from_yaml(
      fmt::format("version: 1\nduration: 1\nground: {{contact: false}}\nobjects:\n"
                  "  - mesh: {{file: \"{}\", translation: [0, 0, 1]}}\n"
                  "    material: {{density: 1000, youngs_modulus: 1.0e7, radius: 0.005}}\n",
                  log)));
  EXPECT_TRUE(piece_landings(no_ground, mesh_pieces(no_ground)).empty());
}

}  // namespace
}  // namespace dinam
