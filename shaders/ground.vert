#version 330 core
// A square in the ground plane, centred under the scene; axis_u and axis_v span the plane.
layout(location = 0) in vec2 unit_corner;  // in [-1, 1]²

uniform mat4 clip_from_world;

// Invariant: a depth-only pass and a colour pass give the same depths, which blurred frames rely
// on (their colour pass keeps only fragments at the depth the first pass found).
invariant gl_Position;
uniform vec3 center;
uniform vec3 axis_u;
uniform vec3 axis_v;
uniform float half_size;

uniform vec3 plane_normal;

out vec3 world_position;
out vec2 plane_position;  // m, coordinates along axis_u and axis_v from the plane's origin
out vec3 surface_normal;

void main() {
  vec2 offset = unit_corner * half_size;
  world_position = center + axis_u * offset.x + axis_v * offset.y;
  plane_position = vec2(dot(world_position, axis_u), dot(world_position, axis_v));
  surface_normal = plane_normal;
  gl_Position = clip_from_world * vec4(world_position, 1.0);
}
