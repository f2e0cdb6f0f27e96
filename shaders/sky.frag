#version 330 core
// A vertical gradient from the horizon colour to a deeper blue at the top of the picture, in
// linear light (display.glsl stores it).
in vec2 screen_uv;

uniform vec3 horizon_color;  // linear RGB
uniform vec3 zenith_color;

out vec4 out_color;

void main() {
  out_color = stored_color(mix(horizon_color, zenith_color, clamp(screen_uv.y, 0.0, 1.0)));
}
