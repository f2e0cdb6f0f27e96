#version 330 core
// A triangle that covers the screen, made from gl_VertexID alone (no vertex buffer): the sky
// behind everything, and the passes that read the drawn picture back.
out vec2 screen_uv;

void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  screen_uv = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
}
