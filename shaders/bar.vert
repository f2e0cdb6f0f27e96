#version 330 core
// One instance per bar: a unit cylinder (radius 1 around z, z from 0 to 1) stretched from p0 to
// p1 with the bar's radius. The basis around the axis is built here so the CPU sends only ends.
layout(location = 0) in vec3 unit_position;
layout(location = 1) in vec3 unit_normal;
layout(location = 2) in vec3 instance_p0;
layout(location = 3) in vec3 instance_p1;
layout(location = 4) in float instance_radius;
layout(location = 5) in vec3 instance_color;
layout(location = 6) in vec3 instance_finish;  // roughness, metallic, sheen

uniform mat4 clip_from_world;

// Invariant: a depth-only pass and a colour pass give the same depths, which blurred frames rely
// on (their colour pass keeps only fragments at the depth the first pass found).
invariant gl_Position;

out vec3 world_position;
out vec3 world_normal;
out vec3 base_color;
out vec2 surface_uv;
out vec3 surface_finish;

void main() {
  vec3 axis = instance_p1 - instance_p0;
  float len = length(axis);
  vec3 w = len > 0.0 ? axis / len : vec3(0.0, 0.0, 1.0);
  // Any vector not parallel to w gives a basis; pick the world axis least aligned with it.
  vec3 helper = abs(w.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 u = normalize(cross(helper, w));
  vec3 v = cross(w, u);
  vec3 offset = instance_radius * (u * unit_position.x + v * unit_position.y);
  world_position = instance_p0 + axis * unit_position.z + offset;
  world_normal = u * unit_normal.x + v * unit_normal.y + w * unit_normal.z;
  base_color = instance_color;
  surface_uv = vec2(0.0);
  surface_finish = instance_finish;
  gl_Position = clip_from_world * vec4(world_position, 1.0);
}
