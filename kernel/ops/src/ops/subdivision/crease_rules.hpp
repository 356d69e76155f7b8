#pragma once

// Internal to subdivision: OpenSubdiv's semi-sharp crease arithmetic (Sdc::Crease, Catmark scheme), in
// float as OpenSubdiv keeps sharpness, so that blend weights agree with it to the last bit.

#include <cstdint>
#include <span>

#include "nome/mesh/types.hpp"
#include "nome/ops/crease_options.hpp"

namespace nome {

// Which vertex mask applies: by the vertex's own weight and its count of sharp edges.
enum class VertexRule : std::uint8_t { smooth, dart, crease, corner };

inline bool is_semi_sharp(float w) {
  return w > 0.0f && w < infinite_sharpness;
}

// One level's decay: infinite stays, a weight above 1 loses 1, the rest becomes smooth.
inline float decayed(float w) {
  if (w <= 0.0f) return 0.0f;
  if (w >= infinite_sharpness) return infinite_sharpness;
  return w > 1.0f ? w - 1.0f : 0.0f;
}

inline VertexRule vertex_rule(float vertex_weight, int sharp_edges) {
  if (vertex_weight > 0.0f || sharp_edges > 2) return VertexRule::corner;
  return sharp_edges == 0 ? VertexRule::smooth : sharp_edges == 1 ? VertexRule::dart : VertexRule::crease;
}

// The weights of the child edges at a vertex from those of its parent edges (same order). Chaikin: a
// semi-sharp edge's child takes 3/4 of its weight and 1/4 of the mean of the other semi-sharp ones, less 1.
inline void child_weights_around(CreaseMethod method, std::span<const float> parent, std::span<float> child) {
  float sum = 0.0f;
  int count = 0;
  for (float w : parent)
    if (is_semi_sharp(w)) sum += w, ++count;
  for (size_t i = 0; i < parent.size(); ++i) {
    const float w = parent[i];
    if (method == CreaseMethod::uniform || parent.size() < 2 || count < 2 || !is_semi_sharp(w)) {
      child[i] = decayed(w);
    } else {
      const float others = (sum - w) / float(count - 1);
      const float c = (0.75f * w + 0.25f * others) - 1.0f;
      child[i] = c > 0.0f ? c : 0.0f;
    }
  }
}

// The share of the parent's rule when a vertex's rule changes between parent and child: the mean of the
// weights that decayed to zero on the way, at most 1.
inline float fractional_weight(CreaseMethod method, float parent_vertex, float child_vertex,
                               std::span<const float> parent, std::span<const float> child) {
  int count = 0;
  float sum = 0.0f;
  if (parent_vertex > 0.0f && child_vertex <= 0.0f) count = 1, sum = parent_vertex;
  for (size_t i = 0; i < parent.size(); ++i) {
    const bool decays = method == CreaseMethod::uniform ? parent[i] > 0.0f && parent[i] <= 1.0f
                                                        : parent[i] > 0.0f && child[i] <= 0.0f;
    if (decays) sum += parent[i], ++count;
  }
  if (count == 0) return 0.0f;
  const float weight = sum / float(count);
  return weight > 1.0f ? 1.0f : weight;
}

}  // namespace nome
