#version 330 core
// A bar's capsule, found along the pixel's ray (capsule.vert) and lit like every other surface,
// or (DEPTH_ONLY) only its depth. The depth is written from the hit, so that capsules and other
// surfaces hide each other where they really meet.
in vec3 world_position;
flat in vec3 capsule_p0;
flat in vec3 capsule_p1;
flat in float capsule_radius;
flat in int flat_ends;  // the cylinder alone, without round ends
flat in vec3 base_color;
flat in vec3 surface_finish;

uniform mat4 clip_from_world;
uniform vec3 view_origin;
uniform vec3 view_direction;  // orthographic views; 0 for perspective
uniform float depth_offset;   // added to the depth written (a depth-only pre-pass's margin)
uniform float pixel_angle;    // radians a pixel spans (perspective), or metres (orthographic)
uniform bool multisampled;    // the target has several samples a pixel
#ifdef LINE_PASS
// A thin bar's line (capsule.vert) carries its axis, not the pixel's point: the pixel's ray is
// found from its window position instead.
uniform mat4 world_from_clip;
uniform vec2 viewport_size;  // pixels
#endif

#ifndef DEPTH_ONLY
out vec4 out_color;
#endif

// Distance along the unit ray (origin ro, direction rd) to the capsule between pa and pb of
// radius r, or −1 where the ray misses it (the cylinder, then the sphere at the end it passes,
// unless `round` is false).
float capsule_hit(vec3 ro, vec3 rd, vec3 pa, vec3 pb, float r, bool round) {
  vec3 ba = pb - pa;
  vec3 oa = ro - pa;
  float baba = dot(ba, ba);
  float bard = dot(ba, rd);
  float baoa = dot(ba, oa);
  float rdoa = dot(rd, oa);
  float oaoa = dot(oa, oa);
  float a = baba - bard * bard;
  float b = baba * rdoa - baoa * bard;
  float c = baba * oaoa - baoa * baoa - r * r * baba;
  float h = b * b - a * c;
  float y = baoa;
  if (a > 1e-12 * baba * baba && h >= 0.0) {
    float t = (-b - sqrt(h)) / a;
    y = baoa + t * bard;
    if (y > 0.0 && y < baba) {
      return t;
    }
  } else if (a > 1e-12 * baba * baba) {
    return -1.0;
  }
  if (!round) {
    return -1.0;
  }
  // The round end on the side the ray meets (or, along the axis, the nearer one).
  vec3 oc = (y <= 0.0 || (a <= 1e-12 * baba * baba && bard > 0.0)) ? oa : ro - pb;
  float bc = dot(rd, oc);
  float cc = dot(oc, oc) - r * r;
  float hc = bc * bc - cc;
  return hc > 0.0 ? -bc - sqrt(hc) : -1.0;
}

// The point of segment pa–pb nearest the ray (origin ro, unit direction rd), and the ray's
// parameter where it passes closest to that point.
vec3 nearest_on_segment(vec3 ro, vec3 rd, vec3 pa, vec3 pb, out float t) {
  vec3 ba = pb - pa;
  float baba = max(dot(ba, ba), 1e-20);
  float bard = dot(ba, rd);
  vec3 oa = ro - pa;
  float denominator = baba - bard * bard;
  // Closest points of the two lines, the segment's clamped to its ends.
  float s = denominator > 1e-12 * baba ? (dot(ba, oa) - bard * dot(rd, oa)) / denominator
                                       : 0.0;
  s = clamp(s, 0.0, 1.0);
  vec3 point = pa + s * ba;
  t = dot(point - ro, rd);
  return point;
}

void main() {
  bool orthographic = dot(view_direction, view_direction) > 0.0;
#ifdef LINE_PASS
  vec4 window = world_from_clip * vec4(2.0 * gl_FragCoord.xy / viewport_size - 1.0,
                                       2.0 * gl_FragCoord.z - 1.0, 1.0);
  vec3 position = window.xyz / window.w;
#else
  vec3 position = world_position;
#endif
  vec3 rd = orthographic ? view_direction : normalize(position - view_origin);
  // An orthographic ray starts well before the quad, which lies in front of the capsule (or, for a
  // line, at its axis).
  vec3 ro = orthographic ? position - rd * (4.0 * capsule_radius) : view_origin;
  float t = capsule_hit(ro, rd, capsule_p0, capsule_p1, capsule_radius, flat_ends == 0);
#ifdef DEPTH_ONLY
  if (t < 0.0) {
    discard;
  }
#else
  // Edges are anti-aliased by coverage (alpha to coverage under multisampling): a ray that
  // passes within half a pixel outside the silhouette still covers part of the pixel, and one
  // within half a pixel inside it not all. The footprint of a pixel where the ray passes the
  // bar is `pixel_angle` × the distance (perspective) or `pixel_angle` (orthographic).
  float t_near;
  vec3 core = nearest_on_segment(ro, rd, capsule_p0, capsule_p1, t_near);
  float miss = length(ro + t_near * rd - core) - capsule_radius;  // < 0 inside the silhouette
  float footprint = orthographic ? pixel_angle : pixel_angle * max(t_near, 0.0);
  float coverage = clamp(0.5 - miss / max(footprint, 1e-12), 0.0, 1.0);
  // One sample a pixel: the pixel is the bar's where the ray meets it, as without coverage.
  if ((multisampled ? coverage <= 0.0 : t < 0.0) || (t < 0.0 && flat_ends != 0)) {
    discard;
  }
  if (t < 0.0) {
    // Just outside: the silhouette's point, seen at the ray's closest approach.
    t = t_near;
  }
#endif
  vec3 hit = ro + t * rd;
  vec4 clip = clip_from_world * vec4(hit, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5 + depth_offset, 0.0, 1.0);
#ifndef DEPTH_ONLY
  vec3 ba = capsule_p1 - capsule_p0;
  float along = clamp(dot(hit - capsule_p0, ba) / max(dot(ba, ba), 1e-20), 0.0, 1.0);
  vec3 normal = normalize(hit - capsule_p0 - along * ba);
  // Under multisampling the coverage picks the samples (which then take alpha 1: the renderer
  // turns on alpha to one); with one sample the pixel is the bar's, opaque.
  out_color = vec4(stored_color(shade(base_color, normal, hit, surface_finish)).rgb,
                   multisampled ? coverage : 1.0);
#endif
}
