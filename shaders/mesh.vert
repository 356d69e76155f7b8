// Surfaces: one vertex per face corner, carrying both normals so flat/smooth is a uniform, not a rebuild.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 smooth_normal;
layout(location = 2) in vec3 flat_normal;
layout(location = 3) in uint face;

uniform mat4 model_view;
uniform mat4 projection;
uniform bool use_flat_normals;
uniform vec4 section_plane;  // world space; zero: no section

out vec3 view_position;
out vec3 view_normal;
flat out uint face_id;

void main() {
  vec4 p = model_view * vec4(position, 1.0);
  view_position = p.xyz;
  // The view matrix is a rotation + translation: its 3x3 part maps normals as well.
  view_normal = mat3(model_view) * (use_flat_normals ? flat_normal : smooth_normal);
  face_id = face;
  gl_Position = projection * p;
  gl_ClipDistance[0] = -dot(section_plane, vec4(position, 1.0));
}
