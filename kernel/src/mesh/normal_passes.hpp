#pragma once

#include <algorithm>
#include <mutex>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/mesh/mesh.hpp"
#include "ops/parallel_for.hpp"

namespace nome::normal_passes {

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

// Unit face normals, computed in double precision and stored as T, on up to `threads` threads, the
// degenerate faces listed in order.
template <class T>
void face_normals(const Mesh& mesh, T* out, std::vector<Index>& degenerate, int threads) {
  const Vec3* p = mesh.positions().data();
  const Index* offsets = mesh.face_offsets().data();
  const Index* corners = mesh.corner_vertices().data();
  SharedList list(degenerate);
  // The arrays by value: read through the lambda's references, each store to `out` (which might alias
  // them) would reload them.
  parallel_for(mesh.num_faces(), threads, [&list, out, p, offsets, corners](Index begin, Index end) {
    std::vector<Index> part;
    for (Index f = begin; f < end; ++f) {
      const Vec3 n = unit_face_normal(p, offsets, corners, f);
      out[f] = T(n);
      if (n == Vec3(0.0)) part.push_back(f);
    }
    list.append(part);
  });
  list.sort();
}

// A face f near the middle such that faces [0, f) and [f, F) share no vertex (no component has faces on
// both sides: an offset's two copies of a closed orientable surface), or 0 when there is none.
inline Index disjoint_face_split(const Mesh& mesh) {
  const Index nf = mesh.num_faces();
  if (mesh.num_components() < 2 || nf < 2) return 0;
  Index split = nf / 2;
  while (split < nf && mesh.face_component(split) == mesh.face_component(split - 1)) ++split;
  if (split == nf) return 0;
  std::vector<char> is_before(mesh.num_components(), 0);
  for (Index f = 0; f < split; ++f) is_before[mesh.face_component(f)] = 1;
  for (Index f = split; f < nf; ++f)
    if (is_before[mesh.face_component(f)]) return 0;
  return split;
}

// Vertex normals: per vertex the sum over its fan of s(c) * n_f, then normalized (zero where it vanishes,
// listed unless the vertex is isolated). One pass over the faces in corner order, each face's normal
// added to its vertices' sums with its corner's sign (streaming reads; a gather over the fans reads
// three arrays at random per corner). Measured at a million faces, two threads that each walk all
// corners and add only to their own half of the vertices took longer than one thread; so a second
// thread takes part only where the faces split into two halves without a shared vertex (then each
// vertex's sum is added up in the same order: the same normals on any number of threads).
template <class T>
void vertex_normals(const Mesh& mesh, const T* faces, T* out, std::vector<Index>& degenerate,
                    int threads = 1) {
  using Scalar = typename T::value_type;
  // Where a sum of unit vectors has cancelled down to rounding noise.
  constexpr Scalar vanishing = sizeof(Scalar) == sizeof(double) ? Scalar(1e-12) : Scalar(1e-5);
  const Index* offsets = mesh.face_offsets().data();
  const Index* corners = mesh.corner_vertices().data();
  const signed char* signs = mesh.corner_signs().data();
  parallel_for(mesh.num_vertices(), threads,
               [&](Index begin, Index end) { std::fill(out + begin, out + end, T(0.0)); });
  // Without a negative sign (any consistently oriented surface) no sign is read.
  signed char lowest_sign = 1;
  for (const signed char s : mesh.corner_signs()) lowest_sign = std::min(lowest_sign, s);
  auto scatter = [faces, out, offsets, corners, signs, lowest_sign](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) {
      const T n = faces[f];
      if (lowest_sign > 0)
        for (Index c = offsets[f]; c < offsets[f + 1]; ++c) out[corners[c]] += n;
      else
        for (Index c = offsets[f]; c < offsets[f + 1]; ++c) out[corners[c]] += signs[c] > 0 ? n : -n;
    }
  };
  const Index split = threads > 1 && mesh.num_faces() >= (1u << 16) ? disjoint_face_split(mesh) : 0;
  if (split > 0) {
    std::thread second(scatter, split, mesh.num_faces());
    scatter(0, split);
    second.join();
  } else {
    scatter(0, mesh.num_faces());
  }
  SharedList list(degenerate);
  parallel_for(mesh.num_vertices(), threads, [&](Index begin, Index end) {
    std::vector<Index> part;
    for (Index v = begin; v < end; ++v) {
      T& n = out[v];
      const Scalar len = glm::length(n);
      if (len > vanishing) {
        n *= Scalar(1) / len;
      } else {
        n = T(0.0);
        if (!mesh.is_isolated_vertex(v)) part.push_back(v);
      }
    }
    list.append(part);
  });
  list.sort();
}

}  // namespace nome::normal_passes
