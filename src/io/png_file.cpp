#include "io/png_file.hpp"

#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <system_error>
#include <vector>

#include "core/byte_size.hpp"
#include "core/error.hpp"
#include "core/memory_budget.hpp"
#include "core/output_file.hpp"
#include "core/regular_file.hpp"

namespace dinam {
namespace {

// The most deflate can pack into one byte: a run of one value costs 258 bytes per 2 bits.
constexpr std::uint64_t kDeflateMostRatio = 1032;

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// libpng reports errors by longjmp to the setjmp point; these hand the message back as text.
[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* text = static_cast<std::string*>(png_get_error_ptr(png));
  *text = message;
  png_longjmp(png, 1);
}

void on_png_warning(png_structp /*png*/, png_const_charp /*message*/) {}

// Writes without any C++ object needing destruction between setjmp and a possible longjmp.
bool write_rows(std::FILE* file, const Image& image, const PngOptions& options,
                std::string& error) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  if (png == nullptr) {
    error = "out of memory";
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_compression_level(png, options.compression_level);
  png_set_filter(png, PNG_FILTER_TYPE_BASE,
                 options.filter_rows ? PNG_ALL_FILTERS : PNG_FILTER_NONE);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // The pixels are sRGB-encoded (the renderer's display pass encodes them): say so, with the
  // gAMA and cHRM chunks that readers without sRGB support fall back on.
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, image.rgba.data() + static_cast<std::size_t>(y) * row_bytes);
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void write_png(const std::filesystem::path& path, const Image& image, const PngOptions& options) {
  DINAM_CHECK(image.width > 0 && image.height > 0 &&
              image.rgba.size() == static_cast<std::size_t>(image.width) * image.height * 4);
  // A new temporary beside the final name, renamed into place whole (core/output_file.hpp).
  OutputFile file(path);
  std::string error;
  errno = 0;
  if (!write_rows(file.stream(), image, options, error)) {
    // libpng only says "Write Error"; the system's reason (a full disk, a quota) is in errno.
    if (std::ferror(file.stream()) != 0 && errno != 0) {
      error = std::strerror(errno);
    }
    throw WriteError(fmt::format("cannot write {}: {}", path.string(),
                                 error.empty() ? "disk full or not writable" : error));
  }
  file.commit();
}

std::string png_bytes(const Image& image, const PngOptions& options) {
  DINAM_CHECK(image.width > 0 && image.height > 0 &&
              image.rgba.size() == static_cast<std::size_t>(image.width) * image.height * 4);
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* stream = open_memstream(&buffer, &size);
  if (stream == nullptr) {
    throw RuntimeError("cannot encode a PNG in memory: out of memory");
  }
  std::string error;
  const bool written = write_rows(stream, image, options, error);
  std::fclose(stream);  // sets buffer and size
  std::string bytes = written ? std::string(buffer, size) : std::string();
  std::free(buffer);
  if (!written) {
    throw RuntimeError(fmt::format("cannot encode a PNG in memory: {}", error));
  }
  return bytes;
}

namespace {

// Like write_rows, no C++ object may be made between setjmp and a possible longjmp, which would
// skip its destructor: the row pointers live in the caller (the sanitizer build caught the leak a
// cut-off file caused).
// `most_bytes` bounds the decoded pixels (8-bit RGBA) the header may claim: beyond it the rows are
// never allocated, and `claimed` holds the width and height the header gave.
bool read_rows(std::FILE* file, std::uint64_t most_bytes, Image& image,
               std::vector<png_bytep>& rows, std::array<std::uint64_t, 2>& claimed,
               std::string& error) {
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  if (png == nullptr) {
    error = "out of memory";
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, file);
  png_read_info(png, info);
  // Whatever the file holds, hand back 8-bit RGBA.
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
  png_read_update_info(png, info);
  claimed = {png_get_image_width(png, info), png_get_image_height(png, info)};
  if (claimed[0] * claimed[1] * 4 > most_bytes) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  image.width = static_cast<int>(png_get_image_width(png, info));
  image.height = static_cast<int>(png_get_image_height(png, info));
  image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4);
  rows.resize(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y) {
    rows[static_cast<std::size_t>(y)] =
        image.rgba.data() + static_cast<std::size_t>(y) * image.width * 4;
  }
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

// Reads the PNG `file` (null where it could not be opened) that `path` names.
Image read_png_file(FilePtr file, const std::filesystem::path& path) {
  if (!file) {
    throw RuntimeError(fmt::format("cannot open {}: {}", path.string(), std::strerror(errno)));
  }
  unsigned char signature[8] = {};
  if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0) {
    throw RuntimeError(fmt::format("{} is not a PNG file", path.string()));
  }
  // What its header may claim: no more than its bytes can hold compressed (deflate packs at most
  // 1032 bytes into one, for a picture of one colour), nor than half the memory available. A
  // 16 kB file whose header says 65 535 × 65 535 would otherwise be given 17 GB before a row of
  // it is read.
  struct stat info {};
  const std::uint64_t file_bytes =
      ::fstat(::fileno(file.get()), &info) == 0 ? static_cast<std::uint64_t>(info.st_size) : 0;
  std::uint64_t most = kDeflateMostRatio * file_bytes + (1u << 20);
  if (const MemoryBudget budget = available_memory(); budget.bytes > 0) {
    most = std::min(most, budget.bytes / 2);
  }
  Image image;
  std::vector<png_bytep> rows;
  std::string error;
  std::array<std::uint64_t, 2> claimed{0, 0};
  std::rewind(file.get());
  if (!read_rows(file.get(), most, image, rows, claimed, error)) {
    if (const std::uint64_t bytes = claimed[0] * claimed[1] * 4; bytes > most) {
      throw UserError(
          FileLoc{path.string()},
          fmt::format("its header claims {} × {} pixels ({} decoded), more than its "
                      "{} bytes can hold or the memory allows ({} at most): a damaged "
                      "or forged PNG",
                      claimed[0], claimed[1], byte_size(bytes), file_bytes, byte_size(most)));
    }
    throw RuntimeError(fmt::format("cannot read {}: {}", path.string(), error));
  }
  return image;
}

}  // namespace

Image read_png(const std::filesystem::path& path) {
  return read_png_file(FilePtr(std::fopen(path.c_str(), "rb")), path);
}

Image read_regular_png(const std::filesystem::path& path, const std::string& what) {
  const int fd = open_regular_file(path, what);
  FilePtr file(fd < 0 ? nullptr : ::fdopen(fd, "rb"));
  if (fd >= 0 && !file) {
    ::close(fd);
  }
  return read_png_file(std::move(file), path);
}

}  // namespace dinam
