#pragma once
// A number drawn into an image in a 5 × 7 pixel font of the ten digits, each pixel a square of
// `scale`: the frame numbers under a contact sheet's pictures. No font library for ten glyphs.
#include <string>

#include "core/image.hpp"

namespace dinam {

// The label's size in pixels, for `digits` digits: 6 × scale a digit (5 and a space) less the
// last space, 7 × scale high.
int digit_label_width(int digits, int scale);
int digit_label_height(int scale);

// Draws the decimal digits of `text` (others are skipped) with their top left corner at (x, y),
// in `rgb`, clipped to the image.
void draw_digit_label(Image& image, int x, int y, const std::string& text, int scale,
                      const unsigned char rgb[3]);

}  // namespace dinam
