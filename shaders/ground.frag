#version 330 core
// A soft checkerboard that takes the light's shadows and fades into the horizon colour with
// distance from the eye, so the plane's far edge never shows. Linear light
// (display.glsl stores it).
in vec3 world_position;
in vec2 plane_position;

uniform vec3 plane_normal;
uniform float fade_distance;  // m; fully faded at this distance from the eye
uniform float tile_size;  // m; 0 for a plain ground

out vec4 out_color;

void main() {
  // tile_size 0 asks for a plain ground.
  float checker = 0.5;
  if (tile_size > 0.0) {
    vec2 cell = floor(plane_position / tile_size);
    checker = mod(cell.x + cell.y, 2.0);
  }
  vec3 albedo = mix(vec3(0.50, 0.48, 0.45), vec3(0.60, 0.58, 0.54), checker);
  vec3 color = shade_matte(albedo, plane_normal, world_position);
  float fade = smoothstep(0.15 * fade_distance, fade_distance, length(world_position - eye_position));
  out_color = stored_color(mix(color, horizon_color, fade));
}
