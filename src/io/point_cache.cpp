#include "io/point_cache.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstring>

#include "core/error.hpp"

namespace dinam {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the point cache byte order is written for little-endian machines");

constexpr char kPc2Signature[12] = {'P', 'O', 'I', 'N', 'T', 'C', 'A', 'C', 'H', 'E', '2', '\0'};
constexpr std::uint64_t kPc2HeaderBytes = 32;

// 4-byte values in a file's byte order: PC2 is little-endian like the machine, MDD big-endian.
void put32(char* out, std::uint32_t bits, bool big_endian) {
  if (big_endian) {
    bits = __builtin_bswap32(bits);
  }
  std::memcpy(out, &bits, 4);
}
std::uint32_t get32(const char* in, bool big_endian) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, in, 4);
  return big_endian ? __builtin_bswap32(bits) : bits;
}
void put_float(char* out, float value, bool big_endian) {
  put32(out, std::bit_cast<std::uint32_t>(value), big_endian);
}
float get_float(const char* in, bool big_endian) {
  return std::bit_cast<float>(get32(in, big_endian));
}
void put_int(char* out, std::int32_t value, bool big_endian) {
  put32(out, static_cast<std::uint32_t>(value), big_endian);
}
std::int32_t get_int(const char* in, bool big_endian) {
  return static_cast<std::int32_t>(get32(in, big_endian));
}

bool big_endian(PointCacheFormat format) {
  return format == PointCacheFormat::kMdd;
}

std::vector<char> encode_header(const PointCacheHeader& header) {
  std::vector<char> bytes(header.header_bytes());
  if (header.format == PointCacheFormat::kPc2) {
    std::memcpy(bytes.data(), kPc2Signature, sizeof(kPc2Signature));
    put_int(&bytes[12], 1, false);
    put_int(&bytes[16], header.point_count, false);
    put_float(&bytes[20], header.start_frame, false);
    put_float(&bytes[24], header.sample_rate, false);
    put_int(&bytes[28], header.sample_count, false);
  } else {
    put_int(&bytes[0], header.sample_count, true);
    put_int(&bytes[4], header.point_count, true);
    for (std::size_t k = 0; k < header.times.size(); ++k) {
      put_float(&bytes[8 + 4 * k], header.times[k], true);
    }
  }
  return bytes;
}

[[noreturn]] void throw_bad_cache(const std::filesystem::path& path, const std::string& what,
                                  const char* remedy) {
  throw UserError(FileLoc{path.string()}, fmt::format("{}; {}", what, remedy));
}

}  // namespace

const char* extension(PointCacheFormat format) {
  return format == PointCacheFormat::kPc2 ? "pc2" : "mdd";
}

std::uint64_t PointCacheHeader::header_bytes() const {
  return format == PointCacheFormat::kPc2 ? kPc2HeaderBytes
                                          : 8 + 4 * static_cast<std::uint64_t>(sample_count);
}

PointCacheWriter::PointCacheWriter(std::filesystem::path path, PointCacheHeader header)
    : path_(std::move(path)), header_(std::move(header)), buffer_(header_.sample_bytes()) {
  DINAM_CHECK(header_.format == PointCacheFormat::kPc2 ||
              header_.times.size() == static_cast<std::size_t>(header_.sample_count));
  out_.open(path_, std::ios::binary | std::ios::trunc);
  check_stream("create");
  const std::vector<char> bytes = encode_header(header_);
  out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  check_stream("write");
}

void PointCacheWriter::add_sample(const Vec3f* points) {
  DINAM_CHECK(samples_written_ < header_.sample_count);
  const bool big = big_endian(header_.format);
  for (std::int32_t i = 0; i < header_.point_count; ++i) {
    for (int c = 0; c < 3; ++c) {
      put_float(&buffer_[12 * static_cast<std::size_t>(i) + 4 * c], points[i][c], big);
    }
  }
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  check_stream("write");
  ++samples_written_;
}

void PointCacheWriter::close() {
  DINAM_CHECK(samples_written_ == header_.sample_count);
  out_.close();
  check_stream("write");
}

void PointCacheWriter::check_stream(const char* doing) {
  if (!out_) {
    throw WriteError(fmt::format("cannot {} the point cache {}: {}", doing, path_.string(),
                                 std::strerror(errno)));
  }
}

PointCacheHeader read_point_cache_header(const std::filesystem::path& path, PointCacheFormat format,
                                         const char* remedy) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw_bad_cache(path, fmt::format("cannot open the point cache: {}", std::strerror(errno)),
                    remedy);
  }
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  return read_point_cache_header(in, ec ? 0 : size, path, format, remedy);
}

PointCacheHeader read_point_cache_header(std::istream& in, std::uintmax_t size,
                                         const std::filesystem::path& path, PointCacheFormat format,
                                         const char* remedy) {
  PointCacheHeader header;
  header.format = format;
  std::array<char, kPc2HeaderBytes> bytes{};
  const std::size_t fixed = format == PointCacheFormat::kPc2 ? kPc2HeaderBytes : 8;
  if (!in.read(bytes.data(), static_cast<std::streamsize>(fixed))) {
    throw_bad_cache(path, "the file is shorter than a point cache header", remedy);
  }
  if (format == PointCacheFormat::kPc2) {
    if (std::memcmp(bytes.data(), kPc2Signature, sizeof(kPc2Signature)) != 0) {
      throw_bad_cache(path, "the file does not start with POINTCACHE2", remedy);
    }
    if (get_int(&bytes[12], false) != 1) {
      throw_bad_cache(path, fmt::format("PC2 version {} is not 1", get_int(&bytes[12], false)),
                      remedy);
    }
    header.point_count = get_int(&bytes[16], false);
    header.start_frame = get_float(&bytes[20], false);
    header.sample_rate = get_float(&bytes[24], false);
    header.sample_count = get_int(&bytes[28], false);
  } else {
    header.sample_count = get_int(&bytes[0], true);
    header.point_count = get_int(&bytes[4], true);
  }
  if (header.point_count < 0 || header.sample_count < 0) {
    throw_bad_cache(path, "the header gives a negative count", remedy);
  }
  // What the header claims is checked against the file's size before anything is made from it:
  // a file of a few bytes that claims a billion frames would otherwise have its table of times
  // (or a track) allocated first. The claim is reckoned in long double: 12 bytes × 2³¹ points ×
  // 2³¹ samples overflows 64 bits.
  const long double claimed = static_cast<long double>(header.header_bytes()) +
                              static_cast<long double>(header.sample_count) * 12.0L *
                                  static_cast<long double>(header.point_count);
  if (static_cast<long double>(size) != claimed) {
    throw_bad_cache(
        path,
        fmt::format("the file has {} bytes where its header promises {:.0f} ({} "
                    "samples of {} points)",
                    size, static_cast<double>(claimed), header.sample_count, header.point_count),
        remedy);
  }
  if (format == PointCacheFormat::kMdd) {
    std::vector<char> times(4 * static_cast<std::size_t>(header.sample_count));
    if (!in.read(times.data(), static_cast<std::streamsize>(times.size()))) {
      throw_bad_cache(path, "the file ends inside its table of frame times", remedy);
    }
    header.times.resize(static_cast<std::size_t>(header.sample_count));
    for (std::size_t k = 0; k < header.times.size(); ++k) {
      header.times[k] = get_float(&times[4 * k], true);
    }
  }
  return header;
}

void read_point_cache_sample(std::istream& in, const std::filesystem::path& path,
                             const PointCacheHeader& header, std::int32_t sample, Vec3f* points,
                             const char* remedy) {
  DINAM_CHECK(sample >= 0 && sample < header.sample_count);
  std::vector<char> bytes(header.sample_bytes());
  in.seekg(static_cast<std::streamoff>(header.header_bytes() + sample * header.sample_bytes()));
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()))) {
    throw_bad_cache(path, fmt::format("cannot read sample {}", sample), remedy);
  }
  const bool big = big_endian(header.format);
  for (std::int32_t i = 0; i < header.point_count; ++i) {
    for (int c = 0; c < 3; ++c) {
      points[i][c] = get_float(&bytes[12 * static_cast<std::size_t>(i) + 4 * c], big);
    }
    // dinam never writes one (the integrator stops first); a NaN or an infinity would reach the
    // framing and the drawing as garbage, so a cache that holds one is refused by name.
    if (!points[i].allFinite()) {
      throw_bad_cache(
          path,
          fmt::format("point {} of sample {} (frame {}) is not a finite position "
                      "({}, {}, {})",
                      i, sample, sample + 1, points[i].x(), points[i].y(), points[i].z()),
          remedy);
    }
  }
}

}  // namespace dinam
