#pragma once
// PNG frames through libpng. Writing goes to "<name>.tmp" and is renamed when complete, so no
// half-written file ever carries the final name.
#include <filesystem>
#include <string>

#include "core/image.hpp"

namespace dinam {

// zlib level 1 with no row filter: about five times faster than libpng's defaults on rendered
// frames, for files about a third larger (they are intermediate; the movie is the product).
struct PngOptions {
  int compression_level = 1;  // 0 (none) to 9 (smallest)
  bool filter_rows = false;
};

// Throws RuntimeError naming the path on failure; the temporary file is removed.
void write_png(const std::filesystem::path& path, const Image& image,
               const PngOptions& options = {});

// The PNG file's bytes, in memory (a report embeds them). Throws RuntimeError on failure.
std::string png_bytes(const Image& image, const PngOptions& options = {});

// Reads any 8-bit PNG as RGBA. Throws RuntimeError naming the path on failure.
Image read_png(const std::filesystem::path& path);

// The same for a file read only as a regular file of its folder, never through a link (a golden
// image): `what` names it in the message that refuses a link or a special file.
Image read_regular_png(const std::filesystem::path& path, const std::string& what);

}  // namespace dinam
