#pragma once
// Point caches: every frame's vertex positions of one mesh, in the two formats that animation
// packages read without a plug-in. The points are a mesh's vertices in its own order (for dinam,
// an object's nodes), so the cache moves the rest mesh written beside it (cache/obj_file.hpp); a
// scene's `pin_motion: {point_cache: …}` reads one as the path its pinned nodes follow.
//
//  - PC2 (3ds Max's Point Cache 2, Blender's Mesh Cache modifier): little-endian. A 32-byte
//    header: char[12] "POINTCACHE2\0", int32 version (1), int32 point count, float32 start frame,
//    float32 sample rate (frames per sample), int32 sample count; then each sample's points as
//    float32 x, y, z.
//  - MDD (LightWave's, read by Blender and Houdini's MDD node): big-endian. int32 frame count,
//    int32 point count, one float32 time in seconds per frame, then each frame's points as
//    float32 x, y, z.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace dinam {

enum class PointCacheFormat { kPc2, kMdd };

// "pc2" or "mdd", the file extension of each format.
const char* extension(PointCacheFormat format);

struct PointCacheHeader {
  PointCacheFormat format = PointCacheFormat::kPc2;
  std::int32_t point_count = 0;
  std::int32_t sample_count = 0;
  float start_frame = 1.0f;  // PC2: the frame of the first sample
  float sample_rate = 1.0f;  // PC2: frames from one sample to the next
  std::vector<float> times;  // MDD: (sample_count) s, the time of each sample

  std::uint64_t header_bytes() const;  // where the first sample starts
  std::uint64_t sample_bytes() const { return 12ull * static_cast<std::uint64_t>(point_count); }
  std::uint64_t file_bytes() const { return header_bytes() + sample_count * sample_bytes(); }
};

// Writes a point cache sample by sample. The header, written first, promises `sample_count`
// samples; close() checks that they came. Throws RuntimeError when the file cannot be written.
class PointCacheWriter {
 public:
  PointCacheWriter(std::filesystem::path path, PointCacheHeader header);
  // `points` holds the header's point_count positions.
  void add_sample(const Vec3f* points);
  void close();

 private:
  void check_stream(const char* doing);

  std::filesystem::path path_;
  PointCacheHeader header_;
  std::ofstream out_;
  std::int32_t samples_written_ = 0;
  std::vector<char> buffer_;  // one sample, in the file's byte order
};

// What a message about a broken point cache tells the user to do: dinam's own caches are
// simulated again; a scene's input is written again by the program that made it.
inline constexpr const char* kSimulateAgain =
    "it is not a complete point cache written by dinam simulate (simulate again to make a new "
    "cache)";
inline constexpr const char* kExportAgain =
    "it is not a complete point cache (export it again from the program that wrote it)";

// Reads and checks a point cache's header (and that the file is as long as it says). Throws
// UserError naming the file, and then `remedy`, when it is not a complete PC2 or MDD file of that
// format.
PointCacheHeader read_point_cache_header(const std::filesystem::path& path, PointCacheFormat format,
                                         const char* remedy = kSimulateAgain);

// The same from a stream already open on `path`, the file being `size` bytes long: a cache's file,
// opened without following a link (core/regular_file.hpp).
PointCacheHeader read_point_cache_header(std::istream& in, std::uintmax_t size,
                                         const std::filesystem::path& path, PointCacheFormat format,
                                         const char* remedy = kSimulateAgain);

// Reads sample `sample` (0-based) into `points` (header.point_count positions). Throws UserError
// naming the file, and then `remedy`, when it cannot be read.
void read_point_cache_sample(std::istream& in, const std::filesystem::path& path,
                             const PointCacheHeader& header, std::int32_t sample, Vec3f* points,
                             const char* remedy = kSimulateAgain);

}  // namespace dinam
