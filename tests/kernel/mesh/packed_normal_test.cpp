#include <catch2/catch.hpp>

#include <random>

#include <glm/gtc/packing.hpp>
#include <glm/vec4.hpp>

#include "nome/mesh/packed_normal.hpp"

using namespace nome;

TEST_CASE("packed normals have glm's bits, unpack within half a step, and turn round exactly", "[kernel]") {
  std::mt19937 rng{3};
  std::uniform_real_distribution<float> component(-1.2f, 1.2f);
  std::vector<glm::vec3> cases = {{0, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {-1, -1, -1}, {2, -3, 1e-9f}};
  // Random vectors (no component a tie between two steps, where glm rounds away from zero, the pack to
  // even), and every step of each field.
  for (int i = 0; i < 10000; ++i) cases.push_back({component(rng), component(rng), component(rng)});
  for (int k = -511; k <= 511; ++k)
    for (int axis = 0; axis < 3; ++axis) {
      glm::vec3 n(component(rng), component(rng), component(rng));
      n[axis] = float(k) / 511.0f;
      cases.push_back(n);
    }
  for (const glm::vec3& n : cases) {
    const PackedNormal p = pack_normal(n);
    CHECK(p == glm::packSnorm3x10_1x2(glm::vec4(n, 0.0f)));
    const glm::vec3 clamped = glm::clamp(n, -1.0f, 1.0f);
    CHECK(glm::all(glm::lessThanEqual(glm::abs(unpack_normal(p) - clamped), glm::vec3(0.5f / 511 + 1e-6f))));
    CHECK(glm::vec4(unpack_normal(p), 0.0f) == glm::unpackSnorm3x10_1x2(p));
    // Turning a normal round turns its packed fields round (the display's Möbius copies rely on it).
    CHECK(negated(p) == pack_normal(-n));
    CHECK(negated(negated(p)) == p);
  }
  CHECK(pack_normal(glm::vec3(0.0f)) == 0u);
}
