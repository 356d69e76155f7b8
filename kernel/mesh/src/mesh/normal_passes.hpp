#pragma once

#include <algorithm>
#include <mutex>
#include <type_traits>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/packed_normal.hpp"
#include "support/parallel_for.hpp"

namespace nome::normal_passes {

// The normal types the passes store (double vectors, or packed for a display) and what they add up in.
inline void store_normal(Vec3& out, const Vec3& n) {
  out = n;
}
inline void store_normal(PackedNormal& out, const Vec3& n) {
  out = pack_normal(glm::vec3(n));
}
inline void store_normal(PackedNormal& out, const glm::vec3& n) {
  out = pack_normal(n);
}
inline const Vec3& summand(const Vec3& n) {
  return n;
}
inline glm::vec3 summand(PackedNormal n) {
  return unpack_normal(n);
}

// Newell's term of the polygon side a -> b.
inline Vec3 newell_term(const Vec3& a, const Vec3& b) {
  return Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
}

// Appends a thread's list to the shared one; the caller sorts once all threads are done.
class SharedList {
 public:
  explicit SharedList(std::vector<Index>& out) : out_(out) { out_.clear(); }
  void append(const std::vector<Index>& part) {
    if (part.empty()) return;
    std::lock_guard lock(mutex_);
    out_.insert(out_.end(), part.begin(), part.end());
  }
  void sort() { std::sort(out_.begin(), out_.end()); }

 private:
  std::vector<Index>& out_;
  std::mutex mutex_;
};

// The passes read the positions of a face's corners and the normals of a fan's faces at random: the
// reads a few dozen items ahead are asked for early (prefetched), so that they overlap instead of each
// waiting for memory in turn. The arithmetic and its order stay as they are.
inline constexpr Index face_prefetch_distance = 16;  // faces
inline constexpr Index fan_prefetch_distance = 64;   // fan corners
inline void prefetch_corner_positions(const Vec3* p, const Index* offsets, const Index* corners, Index f) {
  const Index* c = corners + offsets[f];
  if (offsets[f + 1] - offsets[f] == 4) {
    for (int i = 0; i < 4; ++i) __builtin_prefetch(&p[c[i]]);
  } else {
    for (Index i = 0; i < offsets[f + 1] - offsets[f]; ++i) __builtin_prefetch(&p[c[i]]);
  }
}

// Face f's unit Newell normal, or zero when it is degenerate: its area below 1e-14 times the squared
// length of its longest side (a relative threshold), found in the same walk round the face. A quad's
// Newell normal is the cross product of its diagonals (the same vector in a third of the arithmetic: this
// pass is bound by arithmetic, not memory), compared with its longer diagonal.
inline Vec3 unit_face_normal(const Vec3* p, const Index* offsets, const Index* corners, Index f) {
  Vec3 n(0.0);
  double extent_squared = 0.0;
  if (offsets[f + 1] - offsets[f] == 4) {
    const Index* c = corners + offsets[f];
    const Vec3 d0 = p[c[2]] - p[c[0]], d1 = p[c[3]] - p[c[1]];
    n = glm::cross(d0, d1);
    extent_squared = std::max(glm::dot(d0, d0), glm::dot(d1, d1));
  } else {
    const Vec3* a = &p[corners[offsets[f + 1] - 1]];
    for (Index c = offsets[f]; c < offsets[f + 1]; ++c) {
      const Vec3& b = p[corners[c]];
      n += newell_term(*a, b);
      const Vec3 side = b - *a;
      extent_squared = std::max(extent_squared, glm::dot(side, side));
      a = &b;
    }
  }
  const double len = glm::length(n);
  if (!(len > 1e-14 * extent_squared) || extent_squared == 0.0) return Vec3(0.0);
  return n * (1.0 / len);
}

// Unit face normals, computed in double precision and stored as T (store_normal), on up to `threads` threads,
// the degenerate faces listed in order.
template <class T>
void face_normals(const Mesh& mesh, T* out, std::vector<Index>& degenerate, int threads) {
  const Vec3* p = mesh.positions().data();
  const Index* offsets = mesh.face_offsets().data();
  const Index* corners = mesh.corner_vertices().data();
  const Index last_face = mesh.num_faces() - 1;
  SharedList list(degenerate);
  // The arrays by value: read through the lambda's references, each store to `out` (which might alias
  // them) would reload them.
  parallel_for(
      mesh.num_faces(), threads, [&list, out, p, offsets, corners, last_face](Index begin, Index end) {
        std::vector<Index> part;
        for (Index f = begin; f < end; ++f) {
          prefetch_corner_positions(p, offsets, corners, std::min(f + face_prefetch_distance, last_face));
          const Vec3 n = unit_face_normal(p, offsets, corners, f);
          store_normal(out[f], n);
          if (n == Vec3(0.0)) part.push_back(f);
        }
        list.append(part);
      });
  list.sort();
}

// Vertex normals: per vertex the sum over its fan of s(c) * n_f in fan order, then normalized (zero where
// it vanishes, listed unless the vertex is isolated). A gather: each vertex reads its own fan, so the
// vertices split between threads without sharing a sum, each sum is added up in the same order on any
// number of threads, and the sums are written once, already normalized. (A scatter from the faces reads
// its arrays in order but adds to the sums at random, and only one thread can do it.)
template <class T>
void vertex_normals(const Mesh& mesh, const T* faces, T* out, std::vector<Index>& degenerate,
                    int threads = 1) {
  using Sum = std::decay_t<decltype(summand(T()))>;
  using Scalar = typename Sum::value_type;
  // Where a sum of unit vectors has cancelled down to rounding noise (packed ones: to their steps of
  // 1/511, a few of which a fan adds up).
  constexpr Scalar vanishing = std::is_same_v<T, PackedNormal> ? Scalar(1e-2) : Scalar(1e-12);
  const Index* fan_offsets = mesh.fan_corner_offsets().data();
  const Index* fan = mesh.fan_corners().data();
  const Index last_fan_corner = Index(mesh.fan_corners().size()) - 1;
  const Index* corner_faces = mesh.corner_faces().data();
  const signed char* signs = mesh.corner_signs().data();
  // Without a negative sign (any consistently oriented surface) no sign is read; in a quad mesh (every
  // subdivided one) corner c's face is c / 4, one random read less per corner.
  signed char lowest_sign = 1;
  for (const signed char s : mesh.corner_signs()) lowest_sign = std::min(lowest_sign, s);
  SharedList list(degenerate);
  const auto gather = [&](auto is_quads, auto has_signs) {
    parallel_for(mesh.num_vertices(), threads, [&](Index begin, Index end) {
      std::vector<Index> part;
      for (Index v = begin; v < end; ++v) {
        Sum n(0.0);
        const Index first = fan_offsets[v], last = fan_offsets[v + 1];
        for (Index i = first; i < last; ++i) {
          const Index ahead = fan[std::min(i + fan_prefetch_distance, last_fan_corner)];
          __builtin_prefetch(&faces[is_quads ? ahead >> 2 : corner_faces[ahead]]);
          const Index c = fan[i];
          const Sum face = summand(faces[is_quads ? c >> 2 : corner_faces[c]]);
          n += !has_signs || signs[c] > 0 ? face : -face;
        }
        const Scalar len = glm::length(n);
        if (len > vanishing) {
          store_normal(out[v], n * (Scalar(1) / len));
        } else {
          store_normal(out[v], Sum(0.0));
          if (last > first) part.push_back(v);
        }
      }
      list.append(part);
    });
  };
  const std::bool_constant<true> yes;
  const std::bool_constant<false> no;
  if (mesh.is_quad_mesh())
    lowest_sign > 0 ? gather(yes, no) : gather(yes, yes);
  else
    lowest_sign > 0 ? gather(no, no) : gather(no, yes);
  list.sort();
}

}  // namespace nome::normal_passes
