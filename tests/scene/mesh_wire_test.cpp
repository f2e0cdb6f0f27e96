// The form in which an imported mesh comes back from the child process (scene/mesh_wire.hpp):
// everything a mesh holds survives the trip, and bytes that are not one whole encoding (cut off
// anywhere, a count or a loop past the end, bytes left over) are refused, never read past.
#include "scene/mesh_wire.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

namespace dinam {
namespace {

RawMesh sample_mesh() {
  RawMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(2, 0, 0.5)};
  mesh.uvs = {{0, 1}, {0.5, 1}, {0.5, 0}, {0, 0}, {1, 1}};
  mesh.faces = {{0, 1, 2, 3}, {1, 4, 2}};
  mesh.lines = {{3, 4}};
  mesh.texture = "textures/flag.png";
  mesh.origins = {{"cloth", {"banner", "left"}}, {"", {"rope"}}, {"pole", {}}};
  mesh.face_origin = {0, 2};
  mesh.line_origin = {1};
  mesh.metres_per_unit = 0.01;
  return mesh;
}

void expect_same_mesh(const RawMesh& a, const RawMesh& b) {
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.uvs, b.uvs);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.lines, b.lines);
  EXPECT_EQ(a.texture, b.texture);
  ASSERT_EQ(a.origins.size(), b.origins.size());
  for (std::size_t k = 0; k < a.origins.size(); ++k) {
    EXPECT_EQ(a.origins[k].material, b.origins[k].material);
    EXPECT_EQ(a.origins[k].groups, b.origins[k].groups);
  }
  EXPECT_EQ(a.face_origin, b.face_origin);
  EXPECT_EQ(a.line_origin, b.line_origin);
  EXPECT_EQ(a.metres_per_unit, b.metres_per_unit);
}

TEST(MeshWire, EverythingAMeshHoldsSurvivesTheTrip) {
  const RawMesh mesh = sample_mesh();
  const std::optional<RawMesh> back = decode_mesh(encode_mesh(mesh));
  ASSERT_TRUE(back);
  expect_same_mesh(mesh, *back);

  RawMesh bare;  // no uvs, origins, texture or unit
  bare.vertices = {Vec3(0, 0, 0), Vec3(1, 2, 3)};
  bare.lines = {{0, 1}};
  const std::optional<RawMesh> bare_back = decode_mesh(encode_mesh(bare));
  ASSERT_TRUE(bare_back);
  expect_same_mesh(bare, *bare_back);
  EXPECT_FALSE(bare_back->metres_per_unit);
}

TEST(MeshWire, EveryCutOfAnEncodingAndAnythingAfterItIsRefused) {
  const std::string bytes = encode_mesh(sample_mesh());
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    EXPECT_FALSE(decode_mesh(std::string_view(bytes).substr(0, length))) << length << " bytes";
  }
  EXPECT_FALSE(decode_mesh(bytes + '\0'));
}

TEST(MeshWire, CountsAndLoopsRunningPastTheEndAreRefused) {
  std::string bytes = encode_mesh(sample_mesh());
  // The first count (vertices) made huge: its elements would run far past the end.
  std::string huge_count = bytes;
  huge_count[7] = '\x40';
  EXPECT_FALSE(decode_mesh(huge_count));
  // A face loop claiming more ids than follow: the faces' array starts after the vertices' and
  // the uvs' (a count and the elements each), with its own count, then the first loop's length.
  const std::size_t faces_at = (8 + 5 * sizeof(Vec3)) + (8 + 5 * sizeof(Eigen::Vector2d)) + 8;
  std::string long_loop = bytes;
  long_loop[faces_at] = '\x7f';
  EXPECT_FALSE(decode_mesh(long_loop));
  // A negative loop length.
  std::string negative_loop = bytes;
  negative_loop[faces_at + 3] = '\xff';
  EXPECT_FALSE(decode_mesh(negative_loop));
}

// The most memory this process has held, kB (the kernel's count, not a clock).
long peak_resident_kilobytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// A child may claim a count of groups far beyond the names it sent: refused before room is made
// for them (fuzzing found a claim of 134 million groups, 4 GB of empty strings).
TEST(MeshWire, AGroupCountBeyondTheNamesIsRefusedWithoutMakingRoomForIt) {
  RawMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  mesh.lines = {{0, 1}};
  mesh.origins = {{"rope", {"a"}}};
  mesh.line_origin = {0};
  std::string bytes = encode_mesh(mesh);
  // The group counts' array is the third from the end: (count 1, value 1), then the names'
  // (count, "rope\0a\0") and the unit's (count 0).
  const std::size_t unit = 8;
  const std::size_t names = 8 + 7;
  const std::size_t count_at = bytes.size() - unit - names - sizeof(Index);
  ASSERT_EQ(bytes[count_at], '\x01');
  ASSERT_TRUE(decode_mesh(bytes));
  bytes[count_at + 3] = '\x08';  // 0x08000001 groups: 4.3 GB of strings, were room made
  const long peak_before = peak_resident_kilobytes();
  EXPECT_FALSE(decode_mesh(bytes));
  EXPECT_LT(peak_resident_kilobytes() - peak_before, 100'000);
  bytes[count_at + 3] = '\xff';  // a negative count
  EXPECT_FALSE(decode_mesh(bytes));
}

// The fuzz target's seeds (tests/fuzz/mesh-wire-seeds/, written by hand in this form) are whole
// encodings, so that fuzzing starts from inside the format.
TEST(MeshWire, TheFuzzersSeedsAreWholeEncodings) {
  int seeds = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(DINAM_SOURCE_DIR) / "tests/fuzz/mesh-wire-seeds")) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::optional<RawMesh> mesh = decode_mesh(bytes);
    ASSERT_TRUE(mesh) << entry.path();
    EXPECT_TRUE(mesh->has_edges()) << entry.path();
    EXPECT_EQ(encode_mesh(*mesh), bytes) << entry.path();
    ++seeds;
  }
  EXPECT_GE(seeds, 3);
}

}  // namespace
}  // namespace dinam
