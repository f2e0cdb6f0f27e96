// Linear colour to what is stored, spliced into fragment shaders after their #version line: the
// frame's linear light as it is (for the passes that follow), or, drawn straight to the display,
// exposed, tone mapped (when TONE_MAPPING is defined) and gamma encoded here.
uniform bool direct_to_display;
uniform float exposure_scale;  // 2^exposure

// The ACES filmic fit (Narkowicz 2015), on values scaled by 0.8 so that mid grey stays near mid
// grey.
vec3 filmic(vec3 x) {
  x *= 0.8;
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Display values; `dithered`, by up to half a step of 8 bits (noise.glsl), so that
// the smooth gradients of a frame averaged in floating point (a faint blur) do not band and a
// region's mean is its true value. Frames drawn straight for the display are not dithered: noise
// would double the size of their PNG files.
vec3 display_color(vec3 linear_color, bool dithered) {
  vec3 c = linear_color * exposure_scale;
#ifdef TONE_MAPPING
  c = filmic(c);
#else
  c = clamp(c, 0.0, 1.0);
#endif
  c = pow(c, vec3(1.0 / 2.2));
  if (dithered) {
    c += (pixel_noise() - 0.5) / 255.0;
  }
  return c;
}

vec4 stored_color(vec3 linear_color) {
  return vec4(direct_to_display ? display_color(linear_color, false) : linear_color, 1.0);
}
