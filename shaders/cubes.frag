in vec3 view_position;
in vec3 view_normal;
in vec3 color;

out vec4 fragment;

void main() {
  fragment = vec4(shade(color, normalize(view_normal), view_position), 1.0);
}
