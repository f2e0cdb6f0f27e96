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

void main() {
  bool orthographic = dot(view_direction, view_direction) > 0.0;
  vec3 rd = orthographic ? view_direction : normalize(world_position - view_origin);
  // An orthographic ray starts well before the quad, which lies in front of the capsule.
  vec3 ro = orthographic ? world_position - rd * (4.0 * capsule_radius) : view_origin;
  float t = capsule_hit(ro, rd, capsule_p0, capsule_p1, capsule_radius, flat_ends == 0);
  if (t < 0.0) {
    discard;
  }
  vec3 hit = ro + t * rd;
  vec4 clip = clip_from_world * vec4(hit, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5 + depth_offset, 0.0, 1.0);
#ifndef DEPTH_ONLY
  vec3 ba = capsule_p1 - capsule_p0;
  float along = clamp(dot(hit - capsule_p0, ba) / max(dot(ba, ba), 1e-20), 0.0, 1.0);
  vec3 normal = (hit - capsule_p0 - along * ba) / capsule_radius;
  out_color = stored_color(shade(base_color, normal, hit, surface_finish));
#endif
}
