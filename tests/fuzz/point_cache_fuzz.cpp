// libFuzzer target: any bytes as a point cache, read as a PC2 and as an MDD file (a scene's
// `pin_motion: {point_cache}`, a motion cache's tracks): the header checked against the file's
// size before anything is made from it, then every sample read (at most 64, however many the
// header claims). Reading may refuse them (UserError, as a user sees it); anything else (a crash,
// a sanitizer report, another exception, an allocation the header talked it into) is a bug.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <vector>

#include "core/error.hpp"
#include "fuzz_file.hpp"
#include "io/point_cache.hpp"

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  for (const dinam::PointCacheFormat format :
       {dinam::PointCacheFormat::kPc2, dinam::PointCacheFormat::kMdd}) {
    const std::filesystem::path path = dinam::fuzz::write_input(
        format == dinam::PointCacheFormat::kPc2 ? "input.pc2" : "input.mdd", data, size);
    try {
      const dinam::PointCacheHeader header = dinam::read_point_cache_header(path, format);
      // A sample's points are made only where the file holds a sample (the header's claim is
      // checked against its size): a header of no samples may claim any point count, as a
      // reader that needs none never makes them.
      if (header.sample_count > 0) {
        std::ifstream in(path, std::ios::binary);
        std::vector<dinam::Vec3f> points(static_cast<std::size_t>(header.point_count));
        for (std::int32_t s = 0; s < std::min(header.sample_count, 64); ++s) {
          dinam::read_point_cache_sample(in, path, header, s, points.data());
        }
      }
    } catch (const dinam::UserError&) {
    }
  }
  return 0;
}
