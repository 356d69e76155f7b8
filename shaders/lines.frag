uniform vec4 color;
flat in vec4 line_color;

out vec4 fragment;

void main() {
  fragment = line_color.a > 0.0 ? line_color : color;
}
