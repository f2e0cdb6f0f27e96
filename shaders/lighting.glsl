// Shared lighting, spliced into fragment shaders after their #version line, in linear light: the
// sun (a directional light with a shadow map), light from the sky and the ground, and a GGX
// microfacet highlight over a Lambert base. The program is built with SOFT_SHADOWS, ONE_SHADOW_TAP
// and SKY_LIGHT defined or not (core/look.hpp), never as branches on uniforms, which cost much
// per pixel in Mesa's software rasteriser.
uniform vec3 light_direction;  // towards the sun, unit length
uniform vec3 eye_position;
uniform bool shadows_enabled;
uniform float light_tan;           // tan of the sun's apparent radius
uniform sampler2DShadow shadow_map;
uniform sampler2D shadow_depth;    // the same map read as depths, for the blocker search
uniform mat4 light_from_world;     // to the shadow map's [0, 1]³
uniform vec3 horizon_color;        // linear RGB, as the sky is drawn
uniform vec3 zenith_color;

const float kPi = 3.14159265;
// The sun's radiance times π: a white Lambert surface facing it reflects 0.85.
const float kSunIntensity = 0.85 * kPi;
const vec3 kGroundBounce = vec3(0.22, 0.20, 0.18);  // light the ground sends up
const vec3 kFlatAmbient = vec3(0.27);               // ambient when the sky light is off

// A Poisson disc of 16 points (a common set, whose farthest point is 1.23 from the centre),
// scaled into the unit circle for shadow filtering.
const vec2 kDisc[16] = vec2[](
    vec2(-0.9420, -0.3991) * 0.81, vec2(0.9456, -0.7689) * 0.81, vec2(-0.0942, -0.9294) * 0.81,
    vec2(0.3450, 0.2939) * 0.81, vec2(-0.9159, 0.4577) * 0.81, vec2(-0.8154, -0.8791) * 0.81,
    vec2(-0.3828, 0.2768) * 0.81, vec2(0.9748, 0.7565) * 0.81, vec2(0.4432, -0.9751) * 0.81,
    vec2(0.5374, -0.4737) * 0.81, vec2(-0.2650, -0.4189) * 0.81, vec2(0.7920, 0.1909) * 0.81,
    vec2(-0.2419, 0.9971) * 0.81, vec2(-0.8141, 0.9144) * 0.81, vec2(0.1998, 0.7864) * 0.81,
    vec2(0.1438, -0.1410) * 0.81);

// A per-pixel angle (noise.glsl) that rotates the disc, so that its few taps give fine noise
// rather than visible copies of the shadow.
mat2 disc_rotation() {
  float angle = 6.2831853 * pixel_noise();
  float c = cos(angle);
  float s = sin(angle);
  return mat2(c, s, -s, c);
}

// Fraction of 16 rotated disc taps of radius `radius` (map units) that the light reaches.
float filtered_visibility(vec3 p, float radius, float bias) {
  mat2 rotation = disc_rotation();
  float sum = 0.0;
  for (int i = 0; i < 16; ++i) {
    sum += texture(shadow_map, vec3(p.xy + rotation * kDisc[i] * radius, p.z - bias));
  }
  return sum / 16.0;
}

// 1 where the light reaches, 0 in full shadow, with a depth bias that grows where the surface is
// steep to the light (against shadow acne). Soft: the penumbra of a sun of apparent radius θ
// behind an occluder at depth distance Δ is Δ tan θ wide in map units on either side (the map's
// depth and width span the same length), found from the mean depth of the occluders nearby
// (percentage-closer soft shadows, Fernando 2005). Else a 3×3 filtered edge, or one tap.
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
#ifdef SOFT_SHADOWS
  {
    // Occluders can sit anywhere between the light (depth 0) and the point.
    float search = clamp(p.z * light_tan, texel.x, 0.05);
    mat2 rotation = disc_rotation();
    float blockers = 0.0;
    float blocker_depth = 0.0;
    for (int i = 0; i < 16; i += 2) {
      float d = texture(shadow_depth, p.xy + rotation * kDisc[i] * search).r;
      if (d < p.z - bias) {
        blockers += 1.0;
        blocker_depth += d;
      }
    }
    if (blockers == 0.0) {
      return 1.0;
    }
    float penumbra = (p.z - blocker_depth / blockers) * light_tan;
    return filtered_visibility(p.xyz, max(penumbra, 1.5 * texel.x), bias);
  }
#elif defined(ONE_SHADOW_TAP)
  // One bilinear comparison: the edge is filtered over a texel (a draft, or an instant of a
  // blurred frame, whose instants see the sun from points across its disc).
  return texture(shadow_map, vec3(p.xy, p.z - bias));
#else
  float sum = 0.0;
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      sum += texture(shadow_map, vec3(p.xy + vec2(i, j) * texel, p.z - bias));
    }
  }
  return sum / 9.0;
#endif
}

// What the sky (above the horizon) or the ground's bounce (below) sends along `direction`.
vec3 sky_radiance(vec3 direction) {
  float up = direction.z;
  return up >= 0.0 ? mix(horizon_color, zenith_color, sqrt(up))
                   : mix(horizon_color, kGroundBounce, clamp(-4.0 * up, 0.0, 1.0));
}

// Light arriving on a surface facing `n` from the sky and the ground, per unit albedo.
vec3 ambient_irradiance(vec3 n) {
#ifdef SKY_LIGHT
  vec3 sky = 0.7 * mix(horizon_color, zenith_color, 0.5);
  return mix(kGroundBounce, sky, 0.5 + 0.5 * n.z);
#else
  return kFlatAmbient;
#endif
}

// A matte surface facing `normal` (the ground): the sun's Lambert term and the ambient light,
// without the highlight, reflection and sheen that `shade` adds and a rough ground hardly shows.
vec3 shade_matte(vec3 base_color, vec3 normal, vec3 world_position) {
  vec3 n = normalize(normal);
  if (dot(n, eye_position - world_position) < 0.0) {
    n = -n;
  }
  float sun = max(dot(n, light_direction), 0.0) * light_visibility(world_position, n);
  return base_color * (sun * kSunIntensity / kPi + ambient_irradiance(n));
}

// `finish`: roughness, metallic, sheen (core/look.hpp).
vec3 shade(vec3 base_color, vec3 normal, vec3 world_position, vec3 finish) {
  vec3 v = normalize(eye_position - world_position);
  vec3 n = normalize(normal);
  if (dot(n, v) < 0.0) {
    n = -n;  // two-sided: light the side that faces the eye
  }
  float roughness = clamp(finish.x, 0.03, 1.0);
  float metallic = finish.y;
  float sheen = finish.z;
  float visibility = light_visibility(world_position, n);
  float nv = max(dot(n, v), 1e-3);
  float nl = max(dot(n, light_direction), 0.0);
  vec3 f0 = mix(vec3(0.04), base_color, metallic);
  vec3 diffuse_color = (1.0 - metallic) * base_color;

  // The sun: Lambert plus GGX with Smith's height-correlated visibility and Schlick's Fresnel.
  vec3 h = normalize(light_direction + v);
  float nh = max(dot(n, h), 0.0);
  float a2 = roughness * roughness * roughness * roughness;
  float d = a2 / (kPi * pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
  float a = roughness * roughness;
  float smith = 0.5 / (nl * (nv * (1.0 - a) + a) + nv * (nl * (1.0 - a) + a) + 1e-5);
  vec3 fresnel = f0 + (1.0 - f0) * pow(1.0 - max(dot(v, h), 0.0), 5.0);
  vec3 sun = (diffuse_color / kPi + d * smith * fresnel) * kSunIntensity * nl * visibility;

  // The sky and the ground: diffuse by the facing, glossy by the reflected direction (blurred
  // towards the diffuse light as the finish roughens).
  vec3 irradiance = ambient_irradiance(n);
  vec3 ambient = diffuse_color * irradiance;
#ifdef SKY_LIGHT
  vec3 reflected = mix(sky_radiance(reflect(-v, n)), irradiance, roughness);
  vec3 env_fresnel = f0 + (max(vec3(1.0 - roughness), f0) - f0) * pow(1.0 - nv, 5.0);
  ambient += env_fresnel * reflected;
#endif

  // Sheen: fibres catch light at grazing angles, lit by the sun (wrapped) and the sky.
  vec3 sheen_color = mix(base_color, vec3(1.0), 0.4);
  float grazing = pow(1.0 - nv, 3.0);
  float wrapped = max(dot(n, light_direction) + 0.5, 0.0) / 1.5 * visibility;
  vec3 glow = sheen * grazing * sheen_color * (irradiance + 0.85 * wrapped);

  return sun + ambient + glow;
}
