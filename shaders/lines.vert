// Lines of any width (wireframe, borders, Möbius edges, polylines): segments expanded by lines.geom.
layout(location = 0) in vec3 position;

uniform mat4 model_view;
uniform mat4 projection;
uniform float depth_bias;  // pulls lines in front of the faces they lie on

void main() {
  gl_Position = projection * (model_view * vec4(position, 1.0));
  gl_Position.z -= depth_bias * gl_Position.w;
}
