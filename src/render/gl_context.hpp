#pragma once
// An off-screen OpenGL core-profile context from OSMesa (Mesa's software rasteriser), drawing
// into memory that this object owns.
#include <cstdint>
#include <vector>

namespace dinam {

class GlContext {
 public:
  // Creates a 3.3+ core context of the given size and makes it current. Throws RuntimeError.
  GlContext(int width, int height);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // The default framebuffer: RGBA8, bottom row first (OpenGL's convention).
  const std::vector<std::uint8_t>& pixels() const { return pixels_; }

 private:
  void* context_ = nullptr;  // OSMesaContext
  int width_;
  int height_;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace dinam
