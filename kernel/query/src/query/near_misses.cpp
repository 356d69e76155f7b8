#include "nome/query/near_misses.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "nome/error.hpp"
#include "nome/query/triangle_proximity.hpp"
#include "query/run_parts.hpp"
#include "query/surface_distance.hpp"

namespace nome {
namespace {

// Vertices grouped greedily into patches: each seed (a patch's first vertex) takes the unassigned vertices
// within `radius` of it along the edges.
struct Patches {
  std::vector<Index> offsets{0};
  std::vector<Index> vertices;
  Index size() const { return Index(offsets.size() - 1); }
};

Patches make_patches(const Mesh& surface, const VertexGraph& graph, double radius) {
  Patches patches;
  std::vector<char> assigned(surface.num_vertices(), 0);
  SurfaceDistance distance(graph);
  for (Index seed = 0; seed < surface.num_vertices(); ++seed) {
    if (assigned[seed] || surface.is_isolated_vertex(seed)) continue;
    const Index source[] = {seed};
    distance.run(source, radius, [&](Index v) {
      if (!assigned[v]) {
        assigned[v] = 1;
        patches.vertices.push_back(v);
      }
      return false;
    });
    patches.offsets.push_back(Index(patches.vertices.size()));
  }
  return patches;
}

// A triangle near a patch that the patch's shared search cannot place inside the neighbourhood of every
// vertex of the patch, with its distance from the seed (along the edges, through its nearest corner).
struct PatchCandidate {
  Index triangle;
  double from_seed;        // at most this far (through its nearest settled corner)
  double from_seed_lower;  // and at least this far
  Vec3 lower, upper;       // the triangle's box: most candidates are too far from a vertex to need more
};

// The squared distance from p to the box [lower, upper].
double squared_box_distance(const Vec3& p, const Vec3& lower, const Vec3& upper) {
  const Vec3 outside = glm::max(glm::max(lower - p, p - upper), Vec3(0.0));
  return glm::dot(outside, outside);
}

// A candidate closer to the vertex than the wall whose place in the vertex's neighbourhood the patch's
// search left open.
struct OpenCandidate {
  Index triangle;
  Vec3 point;
  double distance;
};

// One thread's share of the work, with its own search state.
class PatchWorker {
 public:
  PatchWorker(const Mesh& surface, const VertexGraph& graph, const TriangleBvh& bvh,
              const NearMissOptions& options)
      : surface_(surface),
        bvh_(bvh),
        options_(options),
        from_seed_(graph),
        from_vertex_(graph),
        stamp_(surface.num_vertices(), 0) {}

  void check(std::span<const Index> patch, std::vector<NearMiss>& out) {
    const auto& near_crossing = options_.near_crossing;
    if (!near_crossing.empty() &&
        std::all_of(patch.begin(), patch.end(), [&](Index v) { return near_crossing[v] != 0; }))
      return;
    find_candidates(patch);
    if (candidates_.empty()) return;
    for (const Index v : patch)
      if (near_crossing.empty() || !near_crossing[v]) check_vertex(v, out);
  }

 private:
  // Triangles within the wall of the patch's box that the search from its seed cannot place inside the
  // neighbourhood of every vertex of the patch: by the triangle inequality a triangle at s from the seed
  // is within s + r and beyond s - r of a vertex at r from the seed.
  void find_candidates(std::span<const Index> patch) {
    const double wall = options_.min_wall, limit = 3.0 * wall;
    const Vec3 seed_point = surface_.position(patch[0]);
    Vec3 lower(seed_point), upper(lower);
    double reach = 0.0;  // of the patch's vertices from the seed, in space
    for (const Index v : patch) {
      lower = glm::min(lower, surface_.position(v));
      upper = glm::max(upper, surface_.position(v));
      reach = std::max(reach, glm::distance(seed_point, surface_.position(v)));
    }
    reach += wall;
    lower -= Vec3(wall);
    upper += Vec3(wall);
    near_.clear();
    ++current_;
    Index wanted = 0;
    bvh_.visit_box(lower, upper, [&](Index t) {
      Vec3 t_lower = bvh_.triangle_point(t, 0), t_upper = t_lower;
      for (int i = 1; i < 3; ++i) {
        t_lower = glm::min(t_lower, bvh_.triangle_point(t, i));
        t_upper = glm::max(t_upper, bvh_.triangle_point(t, i));
      }
      if (glm::any(glm::greaterThan(t_lower, upper)) || glm::any(glm::lessThan(t_upper, lower))) return;
      const Vec3 outside = glm::max(glm::max(t_lower - seed_point, seed_point - t_upper), Vec3(0.0));
      if (glm::dot(outside, outside) > reach * reach) return;
      near_.push_back(t);
      // A triangle's nearest corner along the edges is at most the distance of any settled corner: one
      // settled corner bounds it. The corner nearest the seed in space is usually settled first.
      auto squared_distance = [&](int i) {
        const Vec3 d = bvh_.triangle_point(t, i) - seed_point;
        return glm::dot(d, d);
      };
      int corner = 0;
      for (int i = 1; i < 3; ++i)
        if (squared_distance(i) < squared_distance(corner)) corner = i;
      want(bvh_.triangle_vertex(t, corner), wanted);
    });
    for (const Index v : patch) want(v, wanted);
    // The search stops once a corner of every nearby triangle and every vertex of the patch is settled:
    // on one smooth sheet that is about the reach, well before 3 x wall. Corners left unsettled keep
    // upper bounds, which only keep more candidates.
    const Index seed[] = {patch[0]};
    const double settled_to =
        from_seed_.run(seed, limit, [&](Index v) { return stamp_[v] == current_ && --wanted == 0; });
    double farthest = 0.0;
    for (const Index v : patch) farthest = std::max(farthest, from_seed_[v]);
    candidates_.clear();
    for (const Index t : near_) {
      double nearest = SurfaceDistance::unreached;
      for (int i = 0; i < 3; ++i) nearest = std::min(nearest, from_seed_[bvh_.triangle_vertex(t, i)]);
      if (nearest + farthest < limit) continue;
      Vec3 t_lower = bvh_.triangle_point(t, 0), t_upper = t_lower;
      for (int i = 1; i < 3; ++i) {
        t_lower = glm::min(t_lower, bvh_.triangle_point(t, i));
        t_upper = glm::max(t_upper, bvh_.triangle_point(t, i));
      }
      candidates_.push_back({t, nearest, std::min(nearest, settled_to), t_lower, t_upper});
    }
  }

  void want(Index v, Index& wanted) {
    Index& stamp = stamp_[v];
    if (stamp != current_) ++wanted;
    stamp = current_;
  }

  void check_vertex(Index v, std::vector<NearMiss>& out) {
    const Vec3& p = surface_.position(v);
    const double limit = 3.0 * options_.min_wall, from_seed = from_seed_[v];
    NearMiss best;
    best.distance = options_.min_wall;
    open_.clear();
    for (const PatchCandidate& c : candidates_) {
      if (c.from_seed + from_seed < limit) continue;
      if (squared_box_distance(p, c.lower, c.upper) >= best.distance * best.distance) continue;
      const Triangle tri{bvh_.triangle_point(c.triangle, 0), bvh_.triangle_point(c.triangle, 1),
                         bvh_.triangle_point(c.triangle, 2)};
      const Vec3 q = closest_point_on_triangle(p, tri);
      const double d = glm::distance(p, q);
      if (d >= best.distance) continue;
      if (c.from_seed_lower - from_seed < limit)
        open_.push_back({c.triangle, q, d});
      else
        best = {v, bvh_.triangles().faces[c.triangle], q, d};
    }
    settle_open(v, best);
    if (best.vertex != no_index) out.push_back(best);
  }

  // The open candidates nearer than the best so far, nearest first, until one is outside the vertex's
  // neighbourhood. The search from the vertex stops once every vertex of those triangles is settled: they
  // lie within the wall in space, so usually well inside the 3 x wall it could go to.
  void settle_open(Index v, NearMiss& best) {
    std::erase_if(open_, [&](const OpenCandidate& c) { return c.distance >= best.distance; });
    if (open_.empty()) return;
    std::sort(open_.begin(), open_.end(),
              [](const OpenCandidate& a, const OpenCandidate& b) { return a.distance < b.distance; });
    ++current_;
    Index wanted = 0;
    for (const OpenCandidate& c : open_)
      for (int i = 0; i < 3; ++i) want(bvh_.triangle_vertex(c.triangle, i), wanted);
    const Index source[] = {v};
    from_vertex_.run(source, 3.0 * options_.min_wall,
                     [&](Index w) { return stamp_[w] == current_ && --wanted == 0; });
    for (const OpenCandidate& c : open_) {
      bool inside = false;
      for (int i = 0; i < 3; ++i)
        inside = inside || from_vertex_[bvh_.triangle_vertex(c.triangle, i)] < 3.0 * options_.min_wall;
      if (inside) continue;
      best = {v, bvh_.triangles().faces[c.triangle], c.point, c.distance};
      return;
    }
  }

  const Mesh& surface_;
  const TriangleBvh& bvh_;
  const NearMissOptions& options_;
  SurfaceDistance from_seed_, from_vertex_;
  std::vector<Index> stamp_;
  Index current_ = 0;
  std::vector<Index> near_;
  std::vector<PatchCandidate> candidates_;
  std::vector<OpenCandidate> open_;
};

}  // namespace

std::vector<char> vertices_near_faces(const Mesh& surface, const std::vector<Index>& faces, double radius) {
  std::vector<char> near(surface.num_vertices(), 0);
  std::vector<Index> sources;
  for (const Index f : faces)
    for (const Index v : surface.face_vertices(f)) sources.push_back(v);
  const VertexGraph graph(surface);
  SurfaceDistance distance(graph);
  distance.run(sources, radius, [](Index) { return false; });
  for (const Index v : distance.touched()) near[v] = distance[v] < radius;
  return near;
}

std::vector<NearMiss> find_near_misses(const Mesh& surface, const TriangleBvh& bvh,
                                       const NearMissOptions& options) {
  if (!(options.min_wall >= 0.0) || !std::isfinite(options.min_wall))
    throw InvalidInputError("find_near_misses: the minimum wall must be positive and finite, got " +
                            std::to_string(options.min_wall));
  if (options.min_wall == 0.0 || surface.num_faces() == 0) return {};
  // Patches of radius 3/4 wall: a triangle of the vertex's own sheet within a wall of it is then within
  // 3 walls of it through the seed (3/4 + 3/4 + a wall, with room for paths along edges).
  const VertexGraph graph(surface);
  const Patches patches = make_patches(surface, graph, 0.75 * options.min_wall);
  const int count = std::max(1, std::min(options.threads, 2));
  std::vector<std::vector<NearMiss>> found(count);
  run_parts(count, [&](int part) {
    PatchWorker worker(surface, graph, bvh, options);
    for (Index p = Index(part); p < patches.size(); p += Index(count)) {
      const std::span<const Index> patch(patches.vertices.data() + patches.offsets[p],
                                         patches.offsets[p + 1] - patches.offsets[p]);
      worker.check(patch, found[part]);
    }
  });
  std::vector<NearMiss> misses;
  for (auto& part : found) misses.insert(misses.end(), part.begin(), part.end());
  std::sort(misses.begin(), misses.end(),
            [](const NearMiss& a, const NearMiss& b) { return a.vertex < b.vertex; });
  return misses;
}

}  // namespace nome
