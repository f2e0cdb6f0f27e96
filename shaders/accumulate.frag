#version 330 core
// Adds one instant of the frame, weighted, to the frame's sum (blended additively): its linear
// colour, dimmed by the ambient occlusion blurred over 4×4 pixels (which averages the rotated
// sampling pattern away).
in vec2 screen_uv;

uniform sampler2D scene_color;  // linear RGB
uniform sampler2D occlusion;    // openness, 1 where nothing is near
uniform bool use_occlusion;
uniform float weight;           // 1 / the number of instants

out vec4 out_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 color = texelFetch(scene_color, pixel, 0).rgb;
  if (use_occlusion) {
    ivec2 last = textureSize(occlusion, 0) - 1;
    float sum = 0.0;
    for (int i = -2; i < 2; ++i) {
      for (int j = -2; j < 2; ++j) {
        sum += texelFetch(occlusion, clamp(pixel + ivec2(i, j), ivec2(0), last), 0).r;
      }
    }
    color *= sum / 16.0;
  }
  out_color = vec4(weight * color, weight);
}
