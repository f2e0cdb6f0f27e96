// Interleaved gradient noise (Jimenez 2014), spliced into fragment shaders after their #version
// line: a value in [0, 1) per pixel that neighbouring pixels spread evenly, for rotating sampling
// patterns and for dither, so that few samples give fine noise rather than visible patterns.
float pixel_noise() {
  return fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
}
