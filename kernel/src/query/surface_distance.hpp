#pragma once

#include <algorithm>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/mesh/mesh.hpp"

namespace nome {

// Each edge's length, for SurfaceDistance.
inline std::vector<double> edge_lengths(const Mesh& mesh) {
  std::vector<double> lengths(mesh.num_edges());
  for (Index e = 0; e < mesh.num_edges(); ++e)
    lengths[e] =
        glm::distance(mesh.position(mesh.edge(e).vertices[0]), mesh.position(mesh.edge(e).vertices[1]));
  return lengths;
}

// Distances along the mesh's edges from a set of source vertices, up to a limit (Dijkstra with a binary
// heap). The distance array is kept between runs and only the vertices a run touched are reset, so one
// instance per thread serves many small searches on a large mesh.
class SurfaceDistance {
 public:
  static constexpr double unreached = std::numeric_limits<double>::infinity();

  SurfaceDistance(const Mesh& mesh, std::span<const double> edge_lengths)
      : mesh_(mesh), lengths_(edge_lengths), distance_(mesh.num_vertices(), unreached) {}

  // Settles vertices nearest first until the next one is at `limit` or beyond; stop(v) may end the
  // search early (it is called once per settled vertex and returns true to stop).
  template <typename Stop>
  void run(std::span<const Index> sources, double limit, Stop&& stop) {
    clear();
    for (const Index s : sources) {
      if (distance_[s] == 0.0) continue;
      distance_[s] = 0.0;
      touched_.push_back(s);
      push(0.0, s);
    }
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), std::greater<>{});
      const auto [d, v] = heap_.back();
      heap_.pop_back();
      if (d > distance_[v]) continue;
      if (d >= limit || stop(v)) break;
      for (const Index e : mesh_.vertex_edges(v)) {
        const Index w = mesh_.edge(e).other_vertex(v);
        const double through = d + lengths_[e];
        if (through >= distance_[w] || through >= limit) continue;
        if (distance_[w] == unreached) touched_.push_back(w);
        distance_[w] = through;
        push(through, w);
      }
    }
    heap_.clear();
  }

  // The distance of v found by the last run (an upper bound for vertices left in the heap when it
  // stopped early), or unreached.
  double operator[](Index v) const { return distance_[v]; }
  std::span<const Index> touched() const { return touched_; }

 private:
  void push(double d, Index v) {
    heap_.push_back({d, v});
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>{});
  }

  void clear() {
    for (const Index v : touched_) distance_[v] = unreached;
    touched_.clear();
  }

  using Entry = std::pair<double, Index>;
  const Mesh& mesh_;
  std::span<const double> lengths_;
  std::vector<double> distance_;
  std::vector<Index> touched_;
  std::vector<Entry> heap_;  // a min-heap kept in a vector so its block is reused
};

}  // namespace nome
