// Wire frames leave no mechanism: a small table welded from straight wires, free in space, has
// exactly the six zero-frequency modes of a rigid body, and its lowest elastic frequency is of
// the order of its legs' own bending. The control, without torsion springs, is a mechanism: its
// joints turn freely about the straight members between them.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <tuple>

#include "dynamics/modal_support.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

constexpr double kSide = 0.4;           // m, the seat's side and the legs' height
constexpr int kSegments = 4;            // bars per member
constexpr double kRadius = 0.003;       // m, of the wire
constexpr double kSteelDensity = 7850;  // kg/m³
constexpr double kYoungs = 2.0e11;      // Pa

// Straight members cut into kSegments bars each and welded where they meet, as OBJ lines written
// to six decimals. Every member is parallel to an axis unless `turn` turns the table: then its
// straight runs are bent by the rounding, up to ~1e-5 rad.
std::string table_obj(const Mat3& turn = Mat3::Identity()) {
  std::map<std::tuple<long, long, long>, int> ids;
  std::string vertices;
  std::string lines;
  auto vertex = [&](const Vec3& p) {
    const auto key = std::make_tuple(std::lround(p.x() * 1e6), std::lround(p.y() * 1e6),
                                     std::lround(p.z() * 1e6));
    if (const auto found = ids.find(key); found != ids.end()) {
      return found->second;
    }
    const Vec3 q = turn * p;
    vertices += "v " + std::to_string(q.x()) + " " + std::to_string(q.y()) + " " +
                std::to_string(q.z()) + "\n";
    const int id = static_cast<int>(ids.size()) + 1;
    ids.emplace(key, id);
    return id;
  };
  auto member = [&](const Vec3& from, const Vec3& to) {
    int previous = vertex(from);
    for (int k = 1; k <= kSegments; ++k) {
      const int next = vertex(from + (to - from) * (static_cast<double>(k) / kSegments));
      lines += "l " + std::to_string(previous) + " " + std::to_string(next) + "\n";
      previous = next;
    }
  };
  const double h = kSide / 2;
  const Vec3 corners[4] = {{-h, -h, kSide}, {h, -h, kSide}, {h, h, kSide}, {-h, h, kSide}};
  for (int c = 0; c < 4; ++c) {
    member(corners[c], corners[(c + 1) % 4]);                       // the seat's frame
    member(corners[c], Vec3(corners[c].x(), corners[c].y(), 0.0));  // a leg
  }
  member(Vec3(-h, 0, kSide), Vec3(h, 0, kSide));  // a slat across: T joints in the seat's plane
  return vertices + lines;
}

Eigen::VectorXd squared_frequencies_of_table(const std::string& object_keys,
                                             const Mat3& turn = Mat3::Identity()) {
  test::TemporaryFolder folder("table");
  std::ofstream(folder.path() / "table.obj") << table_obj(turn);
  const std::string scene =
      "version: 1\nduration: 1\ngravity: [0, 0, 0]\nground: {contact: false}\nobjects:\n"
      "  - mesh: {file: table.obj}\n"
      "    material: {density: " +
      std::to_string(kSteelDensity) + ", youngs_modulus: " + std::to_string(kYoungs) +
      ", radius: " + std::to_string(kRadius) + "}\n" + object_keys;
  const Model model = build_model(read_scene_text(scene, folder.path() / "table.yaml"));
  const test::FreeDofs dofs = test::free_dofs(model);
  return test::squared_frequencies(model, dofs, test::finite_difference_stiffness(model, dofs));
}

// Modes whose ω² is below 1e-9 of the largest: the finite-difference stiffness's noise is
// ~1e-15 of it, and the table's lowest elastic mode is ~1e-5.
int zero_modes(const Eigen::VectorXd& squared) {
  int count = 0;
  for (const double lambda : squared) {
    count += std::abs(lambda) < 1e-9 * squared.maxCoeff() ? 1 : 0;
  }
  return count;
}

// A leg alone as a cantilever: ω₁ = (1.8751)² √(E I / (ρ A L⁴)).
double cantilever_leg_omega() {
  const double area = M_PI * kRadius * kRadius;
  const double moment = area * kRadius * kRadius / 4.0;
  return 1.8751 * 1.8751 *
         std::sqrt(kYoungs * moment / (kSteelDensity * area * std::pow(kSide, 4)));
}

class TableFrame : public ::testing::TestWithParam<std::string> {};

TEST_P(TableFrame, HasOnlyTheRigidBodyModes) {
  const Eigen::VectorXd squared = squared_frequencies_of_table(GetParam());
  ASSERT_EQ(zero_modes(squared), 6);
  // The lowest elastic mode: of the order of a leg's own bending, not a mechanism's near zero.
  const double lowest = std::sqrt(squared[6]);
  EXPECT_GT(lowest, 0.1 * cantilever_leg_omega());
  EXPECT_LT(lowest, 10.0 * cantilever_leg_omega());
}

INSTANTIATE_TEST_SUITE_P(BendingPairs, TableFrame,
                         ::testing::Values("", "    bending_pairs: all\n"));

// Turned off the axes, the table's straight runs come out of the file bent by rounding. Those
// rest angles are taken as straight (model/bending_springs.cpp): a rest bent by ψ0 would make
// straight a point of higher energy, and the finite-difference stiffness, whose step turns a bar
// by ~1e-5 rad, would find spurious soft and negative modes there.
TEST(TableFrame, TurnedOffTheAxesHasOnlyTheRigidBodyModes) {
  const Mat3 turn = (Eigen::AngleAxisd(0.3, Vec3::UnitZ()) * Eigen::AngleAxisd(0.7, Vec3::UnitX()))
                        .toRotationMatrix();
  const Eigen::VectorXd squared = squared_frequencies_of_table("", turn);
  ASSERT_EQ(zero_modes(squared), 6);
  EXPECT_GT(squared.minCoeff(), -1e-9 * squared.maxCoeff());  // nothing below zero
  EXPECT_GT(std::sqrt(squared[6]), 0.1 * cantilever_leg_omega());
}

TEST(TableFrame, WithoutTorsionItIsAMechanism) {
  EXPECT_GT(zero_modes(squared_frequencies_of_table("    torsion: false\n")), 6);
}

}  // namespace
}  // namespace dinam
