#version 330 core
// One instance per bar, drawn as an impostor: a quad across the line of sight, in front of the
// bar and large enough to cover it, inside which the fragment shader finds the bar's capsule (its
// cylinder and two round ends, which also join the bars meeting at a node) along each pixel's
// ray. Two triangles a bar instead of a tessellated cylinder and a sphere per node.
// A bar narrower than a pixel (or a shadow-map texel) is drawn instead as a line along its axis
// (`line_pass`, GL_LINES, two vertices): one primitive a pixel wide instead of two slivers, whose
// pixels the fragment shader (LINE_PASS) finds the capsule along in the same way. Each pass skips
// the bars of the other, so every bar is drawn once.
layout(location = 0) in vec2 corner;  // (±1, ±1): across the bar, along it
layout(location = 2) in vec3 instance_p0;
layout(location = 3) in vec3 instance_p1;
layout(location = 4) in float instance_radius;  // negative: flat ends (DrawList)
layout(location = 5) in vec3 instance_color;
layout(location = 6) in vec3 instance_finish;  // roughness, metallic, sheen

uniform mat4 clip_from_world;
uniform vec3 view_origin;     // the eye of a perspective view
uniform vec3 view_direction;  // the line of sight of an orthographic view (the light's), or 0
uniform float pixel_angle;    // radians a pixel spans (perspective), or metres (orthographic)
uniform bool line_pass;       // drawing the thin bars as lines, not the others as quads

out vec3 world_position;
flat out vec3 capsule_p0;
flat out vec3 capsule_p1;
flat out float capsule_radius;
flat out int flat_ends;
flat out vec3 base_color;
flat out vec3 surface_finish;

void main() {
  vec3 centre = 0.5 * (instance_p0 + instance_p1);
  vec3 axis = instance_p1 - instance_p0;
  float r = abs(instance_radius);
  bool orthographic = dot(view_direction, view_direction) > 0.0;
  // Narrower than a pixel where the bar is nearest the eye.
  float nearest = orthographic ? 1.0 : max(length(centre - view_origin) - 0.5 * length(axis), 0.0);
  bool thin = 2.0 * r < pixel_angle * nearest;
  vec3 sight = orthographic ? view_direction : normalize(centre - view_origin);
  // The quad's plane is across the line of sight, in front of the whole capsule: seen in
  // perspective, every point of the capsule then projects onto it nearer its centre than the
  // point lies, so the capsule's own extent across the sight (half its projected axis plus r
  // along that axis, r across it) bounds what it covers.
  vec3 across_axis = axis - dot(axis, sight) * sight;
  float length_across = length(across_axis);
  vec3 helper = abs(sight.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 e = length_across > 1e-7 * (1.0 + length(axis)) ? across_axis / length_across
                                                      : normalize(cross(sight, helper));
  vec3 f = cross(sight, e);
  world_position = line_pass ? (gl_VertexID == 0 ? instance_p0 : instance_p1)
                             : centre - sight * (0.5 * abs(dot(axis, sight)) + r) +
                   e * corner.y * (0.5 * length_across + r) + f * corner.x * r;
  capsule_p0 = instance_p0;
  capsule_p1 = instance_p1;
  capsule_radius = r;
  flat_ends = instance_radius < 0.0 ? 1 : 0;
  base_color = instance_color;
  surface_finish = instance_finish;
  // A bar the other pass draws: every vertex outside the clip volume, on one side.
  gl_Position = thin == line_pass ? clip_from_world * vec4(world_position, 1.0)
                                  : vec4(2.0, 2.0, 2.0, 1.0);
}
