#version 330 core
// Mesh faces: positions and normals change every frame; colours, texture coordinates and finishes
// do not.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;
layout(location = 3) in vec2 uv;
layout(location = 4) in vec3 finish;  // roughness, metallic, sheen

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
  world_position = position;
  world_normal = normal;
  base_color = color;
  surface_uv = uv;
  surface_finish = finish;
  gl_Position = clip_from_world * vec4(position, 1.0);
}
