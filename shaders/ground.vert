#version 330 core
// A square on the plane z = height, centred under the scene.
layout(location = 0) in vec2 unit_corner;  // in [-1, 1]²

uniform mat4 clip_from_world;
uniform vec3 center;
uniform float half_size;

out vec3 world_position;

void main() {
  world_position = center + vec3(unit_corner * half_size, 0.0);
  gl_Position = clip_from_world * vec4(world_position, 1.0);
}
