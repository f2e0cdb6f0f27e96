#version 330 core
// The cyclorama (render/cyclorama_mesh.hpp): a surface in world space with its own normals,
// shaded as the ground is (ground.frag, plain).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 clip_from_world;

// As ground.vert: a depth-only pass and a colour pass give the same depths.
invariant gl_Position;

out vec3 world_position;
out vec2 plane_position;  // unused: the backdrop is plain
out vec3 surface_normal;

void main() {
  world_position = position;
  plane_position = vec2(0.0);
  surface_normal = normal;
  gl_Position = clip_from_world * vec4(position, 1.0);
}
