// Core profile has no wide lines: each segment becomes a screen-space quad `width` pixels wide with
// square caps, so joints between segments of a chain close.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in vec4 segment_color[];
flat out vec4 line_color;

uniform vec2 viewport_size;
uniform float width;

void main() {
  vec4 a = gl_in[0].gl_Position;
  vec4 b = gl_in[1].gl_Position;
  if (a.w <= 0.0 || b.w <= 0.0) return;  // behind the eye: fitted views never need it
  vec2 half_viewport = 0.5 * viewport_size;
  vec2 sa = a.xy / a.w * half_viewport;
  vec2 sb = b.xy / b.w * half_viewport;
  vec2 along = sb - sa;
  along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  vec2 offset_side = 0.5 * width * across / half_viewport;
  vec2 offset_cap = 0.5 * width * along / half_viewport;
  // Outputs are undefined after each EmitVertex: the colour is written with every corner.
  vec4 corners[4] = vec4[4](vec4(a.xy + (-offset_cap + offset_side) * a.w, a.zw),
                            vec4(a.xy + (-offset_cap - offset_side) * a.w, a.zw),
                            vec4(b.xy + (offset_cap + offset_side) * b.w, b.zw),
                            vec4(b.xy + (offset_cap - offset_side) * b.w, b.zw));
  for (int i = 0; i < 4; ++i) {
    gl_Position = corners[i];
    line_color = segment_color[0];
    EmitVertex();
  }
  EndPrimitive();
}
