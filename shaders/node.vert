#version 330 core
// One instance per node: a unit sphere scaled to the joint's radius, so bars meet smoothly.
layout(location = 0) in vec3 unit_position;
layout(location = 1) in vec3 unit_normal;
layout(location = 2) in vec3 instance_center;
layout(location = 3) in float instance_radius;
layout(location = 4) in vec3 instance_color;
layout(location = 5) in vec3 instance_finish;  // roughness, metallic, sheen

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
  world_position = instance_center + instance_radius * unit_position;
  world_normal = unit_normal;
  base_color = instance_color;
  surface_uv = vec2(0.0);
  surface_finish = instance_finish;
  gl_Position = clip_from_world * vec4(world_position, 1.0);
}
