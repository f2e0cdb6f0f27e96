#version 330 core
// The frame's mean linear colour to display values (display.glsl), dimmed by ambient occlusion
// where it was computed: the occlusion, drawn at half the picture's size, is read back blurred
// over 4 × 4 of its texels (bilinear taps between them), which averages the rotated sampling
// pattern away.
uniform sampler2D frame_color;  // linear RGB: one instant, or the mean of several
uniform sampler2D occlusion;    // openness, 1 where nothing is near
uniform sampler2D scene_depth;  // of the instant the occlusion came from; 1 is the sky
uniform bool use_occlusion;

out vec4 out_color;

void main() {
  vec4 frame = texelFetch(frame_color, ivec2(gl_FragCoord.xy), 0);
  vec3 color = frame.rgb;
#ifdef TRANSPARENT_BACKGROUND
  // What is drawn covers a fraction `frame.a` of the pixel, and its colour was averaged with the
  // empty background's zero: its own colour is the quotient. Stored multiplied by the coverage
  // again, as the frames drawn straight to the display are (read_display divides them).
  float coverage = frame.a;
  color = coverage > 0.0 ? color / coverage : vec3(0.0);
#endif
  // The sky is never occluded (its neighbours' occlusion would bleed into it at the horizon).
  if (use_occlusion && texelFetch(scene_depth, ivec2(gl_FragCoord.xy), 0).r < 1.0) {
    vec2 texel = 1.0 / vec2(textureSize(occlusion, 0));
    vec2 uv = gl_FragCoord.xy / vec2(textureSize(frame_color, 0));
    float sum = 0.0;
    for (int i = -1; i <= 1; i += 2) {
      for (int j = -1; j <= 1; j += 2) {
        sum += texture(occlusion, uv + vec2(i, j) * texel).r;
      }
    }
    color *= sum / 4.0;
  }
#ifdef TRANSPARENT_BACKGROUND
  out_color = vec4(display_color(color, true) * coverage, coverage);
#else
  out_color = vec4(display_color(color, true), 1.0);
#endif
}
