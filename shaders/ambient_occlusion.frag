#version 330 core
// Screen-space ambient occlusion from the drawn depth: the fraction of a hemisphere of points
// around each visible point (radius `radius`, about its normal) that lies behind drawn surfaces,
// counted only where that surface is within reach (Crytek's method, with a normal hemisphere).
// 1 is open; less is enclosed.
uniform sampler2D scene_depth;  // window depth in [0, 1]
uniform mat4 eye_from_clip;
uniform mat4 clip_from_eye;
uniform float radius;           // m
uniform vec2 pixel_size;        // 1 / picture size

out float openness;

// Twelve directions in the +z hemisphere, denser near the centre.
const vec3 kKernel[12] = vec3[](
    vec3(0.12, 0.05, 0.10), vec3(-0.15, 0.12, 0.08), vec3(0.05, -0.22, 0.15),
    vec3(0.30, 0.20, 0.12), vec3(-0.32, -0.18, 0.20), vec3(0.10, 0.40, 0.25),
    vec3(-0.45, 0.30, 0.15), vec3(0.50, -0.35, 0.30), vec3(-0.20, -0.62, 0.25),
    vec3(0.70, 0.25, 0.40), vec3(-0.55, 0.60, 0.35), vec3(0.15, -0.30, 0.90));

vec3 eye_at(vec2 uv) {
  float depth = texture(scene_depth, uv).r;
  vec4 eye = eye_from_clip * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  return eye.xyz / eye.w;
}

void main() {
  // Drawn at half the picture's size: each point is the centre of a full-size pixel (between
  // pixels, the nearest depth texel would be picked by rounding, and neighbours could coincide).
  vec2 uv = (2.0 * floor(gl_FragCoord.xy) + 0.5) * pixel_size;
  if (texture(scene_depth, uv).r >= 1.0) {
    openness = 1.0;  // the sky
    return;
  }
  vec3 p = eye_at(uv);
  // Where the radius spans less than two pixels, the depth buffer cannot resolve what is near
  // (and a grazing ground would occlude itself in stripes): the point counts as open.
  float radius_pixels = radius * clip_from_eye[1][1] / (-p.z * 2.0 * pixel_size.y);
  if (radius_pixels < 2.0) {
    openness = 1.0;
    return;
  }
  // The normal from the neighbours on the nearer side, so that an edge does not blend two
  // surfaces into one slanted one.
  vec3 right = eye_at(uv + vec2(pixel_size.x, 0.0)) - p;
  vec3 left = p - eye_at(uv - vec2(pixel_size.x, 0.0));
  vec3 up = eye_at(uv + vec2(0.0, pixel_size.y)) - p;
  vec3 down = p - eye_at(uv - vec2(0.0, pixel_size.y));
  vec3 dx = abs(right.z) < abs(left.z) ? right : left;
  vec3 dy = abs(up.z) < abs(down.z) ? up : down;
  vec3 n = normalize(cross(dx, dy));
  if (dot(n, p) > 0.0) {
    n = -n;  // facing the eye, which looks down −z from the origin
  }
  float angle = 6.2831853 * pixel_noise();
  vec3 seed = vec3(cos(angle), sin(angle), 0.0);
  vec3 t = seed - n * dot(seed, n);
  t = dot(t, t) > 1e-6 ? normalize(t) : normalize(cross(n, vec3(0.0, 1.0, 0.0)));
  vec3 b = cross(n, t);
  // A sample counts as behind a surface only past a margin: the depth one pixel away changes
  // this much on the point's own surface (a grazing ground would otherwise occlude itself in
  // stripes), and the depth buffer's resolution falls with distance.
  float margin = 0.02 * radius + 1.5 * max(abs(dx.z), abs(dy.z)) + 2e-4 * -p.z;
  float occluded = 0.0;
  for (int k = 0; k < 12; ++k) {
    vec3 s = p + radius * (t * kKernel[k].x + b * kKernel[k].y + n * kKernel[k].z);
    vec4 clip = clip_from_eye * vec4(s, 1.0);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    float surface_z = eye_at(uv).z;
    float in_reach = smoothstep(0.0, 1.0, radius / max(abs(p.z - surface_z), 1e-6));
    occluded += (surface_z >= s.z + margin ? 1.0 : 0.0) * in_reach;
  }
  // Squared, so that a wire lying on the ground (half its hemisphere closed) darkens it clearly.
  openness = pow(1.0 - occluded / 12.0, 2.0);
}
