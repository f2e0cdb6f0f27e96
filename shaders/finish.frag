#version 330 core
// The frame's linear colour to display values: exposure, filmic tone mapping (the ACES fit of
// Narkowicz 2015) or a plain clip, then the display's gamma.
uniform sampler2D frame_color;  // linear RGB, the mean of the frame's instants
uniform float exposure_scale;   // 2^exposure
uniform bool tone_mapping;

out vec4 out_color;

vec3 filmic(vec3 x) {
  // The fit expects scene values scaled so that mid grey stays near mid grey: 0.8 does that.
  x *= 0.8;
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
  vec3 color = texelFetch(frame_color, ivec2(gl_FragCoord.xy), 0).rgb * exposure_scale;
  color = tone_mapping ? filmic(color) : clamp(color, 0.0, 1.0);
  out_color = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
