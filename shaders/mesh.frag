// Two-sided lighting. A face seen from behind is lit with its normal flipped and, under the
// "different" back-face policy, painted in the back colour: on a one-sided surface (Möbius band,
// Klein bottle) both colours meet along the Möbius edges, which is how one-sidedness shows.
// The renderer compiles one variant per set of features in use (FLAT_NORMALS, DIFFERENT_BACK_COLOR,
// FACE_COLORS, SELECTION, SECTION, FILLS_SECTION, defined before this file): llvmpipe runs both sides of a
// branch on a uniform, and at a pixel or two per triangle the shader's length is the frame's.
in vec3 view_position;
in vec3 view_normal;
in float pinch;
flat in uint face_id;
#ifdef SECTION
in float section_distance;
#endif

uniform mat4 model_view;
uniform vec3 front_color;
uniform vec3 back_color;
uniform vec3 selection_color;
// Per face tables (shaders/tables.glsl).
uniform isampler2D face_normals;  // x | y << 10 | z << 20, signed normalized 10 bits each
uniform sampler2D face_colors;    // RGBA; alpha 0 = the front colour
uniform usampler2D face_flags;    // bit 0: selected
uniform float opacity;
uniform vec3 section_color;

out vec4 fragment;

vec3 face_normal(int face) {
  int bits = texelFetch(face_normals, table_texel(face), 0).r;
  // Shifting the field to the top, then back with the sign (arithmetic shift of an int).
  vec3 n = vec3(ivec3(bits << 22, bits << 12, bits << 2) >> 22) / 511.0;
  return mat3(model_view) * n;
}

void main() {
#ifdef SECTION
  // The cut: WebGL2 has no clip distances.
  if (section_distance > 0.0) discard;
#endif
  int face = int(face_id);
#ifdef FLAT_NORMALS
  vec3 n = face_normal(face);
#else
  vec3 n = view_normal;
  if (pinch > 0.0) n += pinch * face_normal(face);
#endif
  // A degenerate face has a zero normal: fall back to the triangle's own plane.
  if (dot(n, n) < 1e-20) n = cross(dFdx(view_position), dFdy(view_position));
  n = normalize(n);
  if (!gl_FrontFacing) n = -n;
  vec3 base = front_color;
#ifdef FACE_COLORS
  vec4 own = texelFetch(face_colors, table_texel(face), 0);
  if (own.a > 0.0) base = own.rgb;
#endif
#ifdef DIFFERENT_BACK_COLOR
  if (!gl_FrontFacing) base = back_color;
#endif
#ifdef FILLS_SECTION
  // Through a section of a closed solid the only back faces in sight are the far walls of its inside:
  // flat, in the section's colour, they fill the cut.
  if (!gl_FrontFacing) {
    fragment = vec4(section_color, opacity);
    gl_FragDepth = gl_FragCoord.z + 2.0 * fwidth(gl_FragCoord.z) + 1e-6;
    return;
  }
#endif
#ifdef SELECTION
  if ((texelFetch(face_flags, table_texel(face), 0).r & 1u) != 0u) base = mix(base, selection_color, 0.65);
#endif
  fragment = vec4(shade(base, n, view_position), opacity);
  // Back faces lose depth ties: along a silhouette the front and back triangles meet at equal depth,
  // and a back-colour fringe there would suggest a one-sided surface where there is none.
  gl_FragDepth = gl_FragCoord.z + (gl_FrontFacing ? 0.0 : 2.0 * fwidth(gl_FragCoord.z) + 1e-6);
}
