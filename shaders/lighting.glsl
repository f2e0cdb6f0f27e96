// Shared lighting, spliced into fragment shaders after their #version line: one directional light
// with a shadow map, a sky/ground hemisphere ambient, Blinn-Phong highlights.
uniform vec3 light_direction;  // towards the light, unit length
uniform vec3 eye_position;
uniform bool shadows_enabled;
uniform sampler2DShadow shadow_map;
uniform mat4 light_from_world;  // to the shadow map's [0, 1]³

// 1 where the light reaches, 0 in full shadow: 3×3 percentage-closer filtering of the map, with
// a depth bias that grows where the surface is steep to the light (against shadow acne).
float light_visibility(vec3 world_position, vec3 normal) {
  if (!shadows_enabled) {
    return 1.0;
  }
  vec4 p = light_from_world * vec4(world_position, 1.0);
  if (p.x < 0.0 || p.x > 1.0 || p.y < 0.0 || p.y > 1.0 || p.z > 1.0) {
    return 1.0;
  }
  float slope = 1.0 - abs(dot(normal, light_direction));
  float bias = 0.0015 + 0.004 * slope;
  vec2 texel = 1.0 / vec2(textureSize(shadow_map, 0));
  float sum = 0.0;
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      sum += texture(shadow_map, vec3(p.xy + vec2(i, j) * texel, p.z - bias));
    }
  }
  return sum / 9.0;
}

vec3 shade(vec3 base_color, vec3 normal, vec3 world_position) {
  vec3 to_eye = normalize(eye_position - world_position);
  vec3 n = normalize(normal);
  if (dot(n, to_eye) < 0.0) {
    n = -n;  // two-sided: light the side that faces the eye
  }
  float visibility = light_visibility(world_position, n);
  float diffuse = max(dot(n, light_direction), 0.0) * visibility;
  vec3 half_vector = normalize(light_direction + to_eye);
  float specular = pow(max(dot(n, half_vector), 0.0), 48.0) * 0.3 * visibility;
  float hemisphere = 0.5 + 0.5 * n.z;
  vec3 ambient = mix(vec3(0.20, 0.18, 0.16), vec3(0.34, 0.38, 0.44), hemisphere);
  return base_color * (ambient + 0.85 * diffuse) + vec3(specular);
}

vec4 encode_display(vec3 linear_color) {
  return vec4(pow(clamp(linear_color, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
