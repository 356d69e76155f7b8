// Surfaces: one vertex per face corner, naming its mesh vertex and face; positions and normals are read
// from buffer textures (three floats per vertex or face), so a slider that moves vertices re-uploads
// those alone, and flat/smooth is a uniform, not a rebuild.
layout(location = 0) in uint corner;  // the vertex id; the top bit: the corner's orientation sign is -1
layout(location = 1) in uint face;

uniform mat4 model_view;
uniform mat4 projection;
uniform bool use_flat_normals;
uniform vec4 section_plane;  // world space; zero: no section
uniform samplerBuffer positions;
uniform samplerBuffer vertex_normals;  // zero at a pinch (the fan's signed normals cancel)
uniform samplerBuffer face_normals;

out vec3 view_position;
out vec3 view_normal;
flat out uint face_id;

vec3 fetch3(samplerBuffer table, uint i) {
  int at = 3 * int(i);
  return vec3(texelFetch(table, at).r, texelFetch(table, at + 1).r, texelFetch(table, at + 2).r);
}

void main() {
  uint v = corner & 0x7fffffffu;
  vec3 position = fetch3(positions, v);
  vec3 flat_normal = fetch3(face_normals, face);
  vec3 normal = flat_normal;
  if (!use_flat_normals) {
    vec3 smooth_normal = fetch3(vertex_normals, v);
    // The vertex normal turned into this face's own orientation (Möbius-aware); a pinch shades flat.
    if (smooth_normal != vec3(0.0)) normal = (corner & 0x80000000u) != 0u ? -smooth_normal : smooth_normal;
  }
  vec4 p = model_view * vec4(position, 1.0);
  view_position = p.xyz;
  // The view matrix is a rotation + translation: its 3x3 part maps normals as well.
  view_normal = mat3(model_view) * normal;
  face_id = face;
  gl_Position = projection * p;
  gl_ClipDistance[0] = -dot(section_plane, vec4(position, 1.0));
}
