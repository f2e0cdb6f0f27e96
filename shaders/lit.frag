#version 330 core
// Bars, joints and surfaces: the shared lighting over the point colour or a texture, in linear
// light (display.glsl stores it).
in vec3 world_position;
in vec3 world_normal;
in vec3 base_color;
in vec2 surface_uv;
in vec3 surface_finish;  // roughness, metallic, sheen

uniform bool use_texture;
uniform sampler2D surface_texture;  // sRGB texture: sampling returns linear colour

out vec4 out_color;

void main() {
  vec3 color = use_texture ? texture(surface_texture, surface_uv).rgb : base_color;
  out_color = stored_color(shade(color, world_normal, world_position, surface_finish));
}
