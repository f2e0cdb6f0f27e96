#version 330 core
// Lambert and Blinn-Phong under one directional light, plus a sky/ground hemisphere ambient.
in vec3 world_position;
in vec3 world_normal;
in vec3 base_color;

uniform vec3 light_direction;  // towards the light, unit length
uniform vec3 eye_position;

out vec4 out_color;

void main() {
  vec3 n = normalize(world_normal);
  vec3 to_eye = normalize(eye_position - world_position);
  if (dot(n, to_eye) < 0.0) {
    n = -n;  // seen from inside: light the side that faces the eye
  }
  float diffuse = max(dot(n, light_direction), 0.0);
  vec3 half_vector = normalize(light_direction + to_eye);
  float specular = pow(max(dot(n, half_vector), 0.0), 48.0) * 0.35;
  float hemisphere = 0.5 + 0.5 * n.z;
  vec3 ambient = mix(vec3(0.18, 0.16, 0.14), vec3(0.32, 0.36, 0.42), hemisphere);
  vec3 color = base_color * (ambient + 0.85 * diffuse) + vec3(specular);
  out_color = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
