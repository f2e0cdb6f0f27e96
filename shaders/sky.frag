#version 330 core
// A vertical gradient from the horizon colour to a deeper blue at the top of the picture, in
// linear light (display.glsl stores it); or, on a transparent background, nothing.
in vec2 screen_uv;

uniform vec3 horizon_color;  // linear RGB
uniform vec3 zenith_color;

out vec4 out_color;

void main() {
#ifdef TRANSPARENT_BACKGROUND
  out_color = vec4(0.0);  // nothing: the frame's alpha says what covers each pixel
#else
  out_color = stored_color(mix(horizon_color, zenith_color, clamp(screen_uv.y, 0.0, 1.0)));
#endif
}
