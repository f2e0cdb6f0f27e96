// PC2 and MDD files: headers byte for byte against the published layouts, round trips through the
// reader, and truncated or foreign files refused.
#include "io/point_cache.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "test_support.hpp"

namespace dinam {
namespace {

std::vector<unsigned char> file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Two points over three samples, each coordinate a distinct value: sample k, point i, axis c is
// k + i / 10 + c / 100 (and negative for point 1, to check the sign bit).
std::vector<std::vector<Vec3f>> sample_points() {
  std::vector<std::vector<Vec3f>> samples(3, std::vector<Vec3f>(2));
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 2; ++i) {
      for (int c = 0; c < 3; ++c) {
        const float value =
            static_cast<float>(k) + 0.1f * static_cast<float>(i) + 0.01f * static_cast<float>(c);
        samples[k][i][c] = i == 1 ? -value : value;
      }
    }
  }
  return samples;
}

void write_cache(const std::filesystem::path& path, PointCacheHeader header) {
  PointCacheWriter writer(path, std::move(header));
  for (const auto& sample : sample_points()) {
    writer.add_sample(sample.data());
  }
  writer.close();
}

TEST(PointCache, Pc2HeaderIsThePublishedLayoutLittleEndian) {
  const test::TemporaryFolder folder("pc2");
  const auto path = folder.path() / "a.pc2";
  write_cache(path, {PointCacheFormat::kPc2, 2, 3, 1.0f, 1.0f, {}});
  const std::vector<unsigned char> bytes = file_bytes(path);
  // char[12] "POINTCACHE2\0", int32 1, int32 2 points, float32 1.0 (0x3F800000) start frame,
  // float32 1.0 sample rate, int32 3 samples; all little-endian.
  const std::vector<unsigned char> expected = {
      'P', 'O', 'I', 'N', 'T', 'C', 'A',  'C',  'H', 'E', '2',  0,    1, 0, 0, 0,
      2,   0,   0,   0,   0,   0,   0x80, 0x3F, 0,   0,   0x80, 0x3F, 3, 0, 0, 0};
  ASSERT_EQ(bytes.size(), 32u + 3 * 2 * 12);
  EXPECT_EQ(std::vector<unsigned char>(bytes.begin(), bytes.begin() + 32), expected);
  // The first coordinate of sample 1, point 0 is 1.0f: 00 00 80 3F right after sample 0.
  const std::size_t sample1 = 32 + 2 * 12;
  EXPECT_EQ(bytes[sample1 + 2], 0x80);
  EXPECT_EQ(bytes[sample1 + 3], 0x3F);
}

TEST(PointCache, MddHeaderIsThePublishedLayoutBigEndian) {
  const test::TemporaryFolder folder("mdd");
  const auto path = folder.path() / "a.mdd";
  write_cache(path, {PointCacheFormat::kMdd, 2, 3, 1.0f, 1.0f, {0.0f, 0.5f, 1.0f}});
  const std::vector<unsigned char> bytes = file_bytes(path);
  // int32 3 frames, int32 2 points, then float32 times 0, 0.5 (0x3F000000), 1.0 (0x3F800000);
  // all big-endian.
  const std::vector<unsigned char> expected = {0, 0, 0,    3, 0, 0, 0,    2,    0, 0,
                                               0, 0, 0x3F, 0, 0, 0, 0x3F, 0x80, 0, 0};
  ASSERT_EQ(bytes.size(), 8u + 3 * 4 + 3 * 2 * 12);
  EXPECT_EQ(std::vector<unsigned char>(bytes.begin(), bytes.begin() + 20), expected);
  // Sample 1, point 0, x = 1.0f, big-endian: 3F 80 00 00.
  const std::size_t sample1 = 20 + 2 * 12;
  EXPECT_EQ(bytes[sample1], 0x3F);
  EXPECT_EQ(bytes[sample1 + 1], 0x80);
}

TEST(PointCache, BothFormatsReadBackBitForBit) {
  const test::TemporaryFolder folder("roundtrip");
  for (const PointCacheFormat format : {PointCacheFormat::kPc2, PointCacheFormat::kMdd}) {
    const auto path = folder.path() / (std::string("a.") + extension(format));
    write_cache(path, {format, 2, 3, 1.0f, 1.0f, {0.0f, 0.05f, 0.1f}});
    const PointCacheHeader header = read_point_cache_header(path, format);
    EXPECT_EQ(header.point_count, 2);
    EXPECT_EQ(header.sample_count, 3);
    if (format == PointCacheFormat::kMdd) {
      EXPECT_EQ(header.times, (std::vector<float>{0.0f, 0.05f, 0.1f}));
    }
    std::ifstream in(path, std::ios::binary);
    const auto expected = sample_points();
    for (int k = 2; k >= 0; --k) {  // any order: each sample is found by its offset
      std::vector<Vec3f> points(2);
      read_point_cache_sample(in, path, header, k, points.data());
      EXPECT_EQ(points, expected[static_cast<std::size_t>(k)]) << extension(format) << " " << k;
    }
  }
}

TEST(PointCache, TruncatedOrForeignFilesAreRefusedNamingTheFile) {
  const test::TemporaryFolder folder("bad");
  const auto path = folder.path() / "a.pc2";
  write_cache(path, {PointCacheFormat::kPc2, 2, 3, 1.0f, 1.0f, {}});
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 1);
  test::expect_user_error([&] { read_point_cache_header(path, PointCacheFormat::kPc2); }, 0,
                          {path.string(), "bytes where its header promises", "simulate again"});
  std::ofstream(path, std::ios::trunc) << "POINTCACHE3 and more than thirty-two bytes of text";
  test::expect_user_error([&] { read_point_cache_header(path, PointCacheFormat::kPc2); }, 0,
                          {"does not start with POINTCACHE2"});
  test::expect_user_error(
      [&] { read_point_cache_header(folder.path() / "none.mdd", PointCacheFormat::kMdd); }, 0,
      {"cannot open"});
}

}  // namespace
}  // namespace dinam
