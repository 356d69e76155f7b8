// Small cubes marking points (selected vertices), one instance each, sized by the caller
// (the report sizes them by the local edge length).
layout(location = 0) in vec3 corner;  // unit cube, [-1, 1]^3
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 center;  // per instance
layout(location = 3) in float half_size;
layout(location = 4) in vec3 instance_color;

uniform mat4 model_view;
uniform mat4 projection;

out vec3 view_position;
out vec3 view_normal;
out vec3 color;

void main() {
  vec4 p = model_view * vec4(center + half_size * corner, 1.0);
  view_position = p.xyz;
  view_normal = mat3(model_view) * normal;
  color = instance_color;
  gl_Position = projection * p;
}
