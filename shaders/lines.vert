// Lines of any width (wireframe, borders, Möbius edges, polylines): segments expanded by lines.geom.
layout(location = 0) in vec3 position;
// A line's own colour (a curve's surface); alpha 0, the value of a set without colours, takes `color`.
layout(location = 1) in vec4 point_color;

out vec4 segment_color;

uniform mat4 model_view;
uniform mat4 projection;
uniform float depth_bias;  // pulls lines in front of the faces they lie on

void main() {
  gl_Position = projection * (model_view * vec4(position, 1.0));
  gl_Position.z -= depth_bias * gl_Position.w;
  segment_color = point_color;
}
