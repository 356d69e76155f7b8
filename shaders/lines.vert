// Lines of any width (wireframe, borders, Möbius edges, polylines): each segment is one instance of a
// screen-space quad `width` pixels wide with square caps, so joints between segments of a chain close.
// Drawn as a 4-vertex triangle strip; gl_VertexID picks the corner (render/segment_source.hpp).
layout(location = 0) in uvec2 ends;  // per instance: the segment's two point ids
// A segment's own colour (a curve's surface); alpha 0, the value of a set without colours, takes `color`.
layout(location = 1) in vec4 segment_color;

uniform sampler2D points;  // vec3 per point id
uniform mat4 model_view;
uniform mat4 projection;
uniform float depth_bias;  // pulls lines in front of the faces they lie on
uniform vec2 viewport_size;
uniform float width;

flat out vec4 line_color;

vec4 clip_position(uint id) {
  vec4 p = projection * (model_view * vec4(texelFetch(points, table_texel(int(id)), 0).xyz, 1.0));
  p.z -= depth_bias * p.w;
  return p;
}

void main() {
  line_color = segment_color;
  vec4 a = clip_position(ends.x);
  vec4 b = clip_position(ends.y);
  if (a.w <= 0.0 || b.w <= 0.0) {  // behind the eye (fitted views never need it): no area, nothing drawn
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec2 half_viewport = 0.5 * viewport_size;
  vec2 sa = a.xy / a.w * half_viewport;
  vec2 sb = b.xy / b.w * half_viewport;
  vec2 along = sb - sa;
  along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  vec2 offset_side = 0.5 * width * across / half_viewport;
  vec2 offset_cap = 0.5 * width * along / half_viewport;
  // Corners 0, 1 at a, 2, 3 at b; the even ones on the left of a -> b.
  bool is_b = gl_VertexID >= 2;
  vec4 end = is_b ? b : a;
  vec2 offset = (is_b ? offset_cap : -offset_cap) + ((gl_VertexID & 1) == 0 ? offset_side : -offset_side);
  gl_Position = vec4(end.xy + offset * end.w, end.zw);
}
