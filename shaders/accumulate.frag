#version 330 core
// Adds one instant of the frame, weighted, to the frame's sum (blended additively).
uniform sampler2D scene_color;  // linear RGB
uniform float weight;           // 1 / the number of instants

out vec4 out_color;

void main() {
  out_color = vec4(weight * texelFetch(scene_color, ivec2(gl_FragCoord.xy), 0).rgb, weight);
}
