// Shared by the lit programs (mesh, cubes); the loader puts it after the #version line.
// Lights fixed to the camera (view space): a key light from the upper left for shape, and a head light
// from the eye so that every surface facing the viewer (after the two-sided flip, all of them) reads.
// A scene that places its own lights (SCENE_LIGHTS, mesh program only) is lit by them alone, as JIPCAD lights
// it: ambient plus each directional light's colour where a face turns towards where it comes from.
#ifdef SCENE_LIGHTS
uniform vec3 scene_ambient;
uniform int scene_light_count;
uniform vec3 scene_light_directions[8];  // view space: where each light travels
uniform vec3 scene_light_colors[8];
#endif

vec3 shade(vec3 base, vec3 n, vec3 view_position) {
#ifdef SCENE_LIGHTS
  vec3 light = scene_ambient;
  for (int i = 0; i < scene_light_count; ++i)
    light += scene_light_colors[i] * max(dot(n, -scene_light_directions[i]), 0.0);
  return base * light;
#else
  const vec3 key = normalize(vec3(-0.35, 0.55, 0.75));
  vec3 to_eye = normalize(-view_position);
  float diffuse = 0.55 * max(dot(n, key), 0.0) + 0.35 * max(dot(n, to_eye), 0.0);
  float specular = 0.2 * pow(max(dot(n, normalize(key + to_eye)), 0.0), 48.0);
  return base * (0.18 + diffuse) + vec3(specular);
#endif
}
