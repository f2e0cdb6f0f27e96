#include "render/digit_label.hpp"

#include <array>
#include <cstdint>

namespace dinam {
namespace {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;

// Each digit's rows, top first, the leftmost pixel in bit 4.
constexpr std::array<std::array<std::uint8_t, kGlyphHeight>, 10> kDigits{{
    {0b01110, 0b10001, 0b10011, 0b10101, 0b11001, 0b10001, 0b01110},  // 0
    {0b00100, 0b01100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110},  // 1
    {0b01110, 0b10001, 0b00001, 0b00010, 0b00100, 0b01000, 0b11111},  // 2
    {0b11111, 0b00010, 0b00100, 0b00010, 0b00001, 0b10001, 0b01110},  // 3
    {0b00010, 0b00110, 0b01010, 0b10010, 0b11111, 0b00010, 0b00010},  // 4
    {0b11111, 0b10000, 0b11110, 0b00001, 0b00001, 0b10001, 0b01110},  // 5
    {0b00110, 0b01000, 0b10000, 0b11110, 0b10001, 0b10001, 0b01110},  // 6
    {0b11111, 0b00001, 0b00010, 0b00100, 0b01000, 0b01000, 0b01000},  // 7
    {0b01110, 0b10001, 0b10001, 0b01110, 0b10001, 0b10001, 0b01110},  // 8
    {0b01110, 0b10001, 0b10001, 0b01111, 0b00001, 0b00010, 0b01100},  // 9
}};

}  // namespace

int digit_label_width(int digits, int scale) {
  return digits > 0 ? (digits * (kGlyphWidth + 1) - 1) * scale : 0;
}

int digit_label_height(int scale) {
  return kGlyphHeight * scale;
}

void draw_digit_label(Image& image, int x, int y, const std::string& text, int scale,
                      const unsigned char rgb[3]) {
  int left = x;
  for (const char c : text) {
    if (c < '0' || c > '9') {
      continue;
    }
    const auto& glyph = kDigits[static_cast<std::size_t>(c - '0')];
    for (int row = 0; row < kGlyphHeight * scale; ++row) {
      for (int column = 0; column < kGlyphWidth * scale; ++column) {
        const int px = left + column;
        const int py = y + row;
        const bool on =
            ((glyph[static_cast<std::size_t>(row / scale)] >> (kGlyphWidth - 1 - column / scale)) &
             1) != 0;
        if (!on || px < 0 || py < 0 || px >= image.width || py >= image.height) {
          continue;
        }
        std::uint8_t* pixel =
            image.rgba.data() + (static_cast<std::size_t>(py) * image.width + px) * 4;
        pixel[0] = rgb[0];
        pixel[1] = rgb[1];
        pixel[2] = rgb[2];
        pixel[3] = 255;
      }
    }
    left += (kGlyphWidth + 1) * scale;
  }
}

}  // namespace dinam
