#version 330 core
// A soft checkerboard (or a plain floor, or the cyclorama that curves up from it) that takes the light's shadows and fades into the horizon
// colour with distance from the eye, so the plane's far edge never shows. Linear light
// (display.glsl stores it).
in vec3 world_position;
in vec2 plane_position;
in vec3 surface_normal;  // the plane's, or the backdrop's (backdrop.vert)
uniform float fade_distance;  // m; fully faded at this distance from the eye
uniform float tile_size;  // m; 0 for a plain ground
uniform vec3 ground_color;   // linear; a plain ground's, or the checker's lighter squares
uniform vec3 checker_color;  // linear; the checker's other squares
// The plane within a cyclorama ends where its curve starts (which would otherwise meet the plane
// at a grazing angle and fight it for the depth); 0 for no cyclorama, and on the cyclorama.
uniform float floor_radius;  // m
uniform vec3 floor_center;
uniform vec3 floor_normal;

out vec4 out_color;

// The share of the lighter squares in the pixel's footprint on the ground: the checkerboard
// averaged over a box as wide as the footprint (the screen derivatives of `squares`), found in
// closed form: the integral of a square wave is a triangle wave, so the box's average is a
// difference of two triangle waves over its width. Where the squares shrink below a pixel it
// tends to ½, the mean of the two colours, instead of aliasing into moiré towards the horizon.
float lighter_share(vec2 squares) {
  vec2 width = max(abs(dFdx(squares)), abs(dFdy(squares))) + 1e-4;
  vec2 sign_average = 2.0 * (abs(fract((squares - 0.5 * width) * 0.5) - 0.5) -
                             abs(fract((squares + 0.5 * width) * 0.5) - 0.5)) / width;
  return 0.5 - 0.5 * sign_average.x * sign_average.y;
}

void main() {
  if (floor_radius > 0.0) {
    vec3 offset = world_position - floor_center;
    if (length(offset - dot(offset, floor_normal) * floor_normal) > floor_radius) {
      discard;
    }
  }
  // tile_size 0 asks for a plain ground.
  float lighter = 1.0;
  if (tile_size > 0.0) {
    lighter = lighter_share(plane_position / tile_size);
  }
  vec3 albedo = mix(checker_color, ground_color, lighter);
  vec3 color = shade_matte(albedo, surface_normal, world_position);
  float fade = smoothstep(0.15 * fade_distance, fade_distance, length(world_position - eye_position));
  out_color = stored_color(mix(color, horizon_color, fade));
}
