// Surfaces: GL vertices shared by the faces around them (render/mesh_display_data.hpp): llvmpipe shades
// each about once, not once per corner. Each triangle's last vertex carries its face id (flat). Positions
// and normals are plain vertex arrays, updated in place when a slider moves vertices; flat/smooth is a
// uniform of the fragment shader, not a rebuild.
layout(location = 0) in vec3 position;
// Unit, or zero at a pinch (the fan's signed normals cancel); packed in 10 bits a component, which GL
// before 4.2 maps to (2c + 1) / 1023 (GLES to c / 511): zero then reads as a vector of length 0.002, not
// exactly zero.
layout(location = 1) in vec3 normal;
layout(location = 2) in uint face;

uniform mat4 model_view;
uniform mat4 projection;
#ifdef SECTION
uniform vec4 section_plane;  // world space: positive on the side cut away
out float section_distance;
#endif

out vec3 view_position;
out vec3 view_normal;
// 1 at a pinch: there the fragment takes its face's normal (exact under interpolation, that normal
// being the same over the triangle).
out float pinch;
flat out uint face_id;

void main() {
  vec4 p = model_view * vec4(position, 1.0);
  view_position = p.xyz;
  // The view matrix is a rotation + translation: its 3x3 part maps normals as well.
  view_normal = mat3(model_view) * normal;
  pinch = dot(normal, normal) < 0.25 ? 1.0 : 0.0;
  face_id = face;
  gl_Position = projection * p;
#ifdef SECTION
  section_distance = dot(section_plane, vec4(position, 1.0));
#endif
}
