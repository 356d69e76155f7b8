#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/mesh/mesh.hpp"

namespace nome {

// The mesh's vertices and edges as a compact graph (CSR: per vertex its neighbours and the edge lengths to
// them, side by side): a search reads one contiguous run per vertex instead of the mesh's edge records.
struct VertexGraph {
  std::vector<Index> offsets;  // vertex v's arcs are [offsets[v], offsets[v + 1])
  struct Arc {
    Index to;
    float length;
  };
  std::vector<Arc> arcs;

  explicit VertexGraph(const Mesh& mesh) : offsets(mesh.num_vertices() + 1, 0) {
    for (Index v = 0; v < mesh.num_vertices(); ++v)
      offsets[v + 1] = offsets[v] + Index(mesh.vertex_edges(v).size());
    arcs.resize(offsets.back());
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
      Index at = offsets[v];
      for (const Index e : mesh.vertex_edges(v)) {
        const Index w = mesh.edge(e).other_vertex(v);
        arcs[at++] = {w, float(glm::distance(mesh.position(v), mesh.position(w)))};
      }
    }
  }
  Index num_vertices() const { return Index(offsets.size() - 1); }
  std::span<const Arc> arcs_of(Index v) const {
    return {arcs.data() + offsets[v], offsets[v + 1] - offsets[v]};
  }
};

// Distances along the mesh's edges from a set of source vertices, up to a limit (Dijkstra with a binary
// heap). The distance array is kept between runs and only the vertices a run touched are reset, so one
// instance per thread serves many small searches on a large mesh. Distances are floats: a heap entry is
// then one 64-bit key (a non-negative float's bits order as the float does), half the size and compared
// as an integer; the print check's thresholds do not need more digits.
class SurfaceDistance {
 public:
  static constexpr double unreached = std::numeric_limits<double>::infinity();

  explicit SurfaceDistance(const VertexGraph& graph)
      : graph_(graph), distance_(graph.num_vertices(), std::numeric_limits<float>::infinity()) {}

  // Settles vertices nearest first until the next one is at `limit` or beyond; stop(v) may end the
  // search early (it is called once per settled vertex and returns true to stop). Returns the distance
  // it settled up to: every vertex not settled is at least that far (a lower bound for them).
  template <typename Stop>
  double run(std::span<const Index> sources, double limit, Stop&& stop) {
    clear();
    const float bound = float(limit);
    for (const Index s : sources) {
      if (distance_[s] == 0.0f) continue;
      distance_[s] = 0.0f;
      touched_.push_back(s);
      push(0.0f, s);
    }
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), std::greater<>{});
      const std::uint64_t key = heap_.back();
      heap_.pop_back();
      const Index v = Index(key);
      const float d = __builtin_bit_cast(float, std::uint32_t(key >> 32));
      if (d > distance_[v]) continue;
      if (d >= bound) break;
      if (stop(v)) {
        heap_.clear();
        return double(d);
      }
      for (const VertexGraph::Arc& arc : graph_.arcs_of(v)) {
        const float through = d + arc.length;
        if (through >= distance_[arc.to] || through >= bound) continue;
        if (distance_[arc.to] == std::numeric_limits<float>::infinity()) touched_.push_back(arc.to);
        distance_[arc.to] = through;
        push(through, arc.to);
      }
    }
    heap_.clear();
    return limit;
  }

  // The distance of v found by the last run (an upper bound for vertices left in the heap when it
  // stopped early), or unreached.
  double operator[](Index v) const { return double(distance_[v]); }
  std::span<const Index> touched() const { return touched_; }

 private:
  // Non-negative floats order as their bits do, so a key sorts by distance first. The builtin stands in
  // for std::bit_cast, which the browser build's standard library lacks.
  void push(float d, Index v) {
    heap_.push_back(std::uint64_t(__builtin_bit_cast(std::uint32_t, d)) << 32 | v);
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>{});
  }

  void clear() {
    for (const Index v : touched_) distance_[v] = std::numeric_limits<float>::infinity();
    touched_.clear();
  }

  const VertexGraph& graph_;
  std::vector<float> distance_;
  std::vector<Index> touched_;
  std::vector<std::uint64_t> heap_;  // a min-heap of keys (distance bits, vertex), its block reused
};

}  // namespace nome
