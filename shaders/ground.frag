#version 330 core
// A soft checkerboard that fades into the sky colour with distance.
in vec3 world_position;

uniform vec3 center;
uniform float half_size;
uniform float tile_size;
uniform vec3 horizon_color;  // linear RGB

out vec4 out_color;

void main() {
  vec2 cell = floor(world_position.xy / tile_size);
  float checker = mod(cell.x + cell.y, 2.0);
  vec3 color = mix(vec3(0.42, 0.40, 0.37), vec3(0.50, 0.48, 0.45), checker);
  float fade = smoothstep(0.35, 1.0, length(world_position.xy - center.xy) / half_size);
  color = mix(color, horizon_color, fade);
  out_color = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
