// Shared by the lit programs (mesh, cubes); the loader puts it after the #version line.
// Two lights fixed to the camera (view space): a key light from the upper left and a weak fill from
// the lower right, so shape reads from any orbit angle. `n` faces the viewer's side of the surface.
vec3 shade(vec3 base, vec3 n, vec3 view_position) {
  const vec3 key = normalize(vec3(-0.35, 0.55, 0.75));
  const vec3 fill = normalize(vec3(0.55, -0.25, 0.6));
  vec3 to_eye = normalize(-view_position);
  float diffuse = 0.72 * max(dot(n, key), 0.0) + 0.22 * max(dot(n, fill), 0.0);
  float specular = 0.22 * pow(max(dot(n, normalize(key + to_eye)), 0.0), 48.0);
  return base * (0.2 + diffuse) + vec3(specular);
}
