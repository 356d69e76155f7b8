#include <algorithm>
#include <mutex>
#include <span>
#include <utility>
#include <vector>

#include "mesh/face_normal.hpp"
#include "nome/mesh/normals.hpp"
#include "ops/parallel_for.hpp"

namespace nome {
namespace {

// Ids that ranges of a parallel_for found, in the order of their ranges.
class RangeIds {
 public:
  void add(Index begin, std::vector<Index> ids) {
    std::lock_guard lock(mutex_);
    parts_.emplace_back(begin, std::move(ids));
  }
  void write(std::vector<Index>& out) {
    std::sort(parts_.begin(), parts_.end());
    out.clear();
    for (const auto& part : parts_) out.insert(out.end(), part.second.begin(), part.second.end());
  }

 private:
  std::mutex mutex_;
  std::vector<std::pair<Index, std::vector<Index>>> parts_;
};

template <class Write>
void face_normals_on(const Mesh& mesh, Normals& out, int threads, const Write& write) {
  const Vec3* p = mesh.positions().data();
  const Index* offsets = mesh.face_offsets().data();
  const Index* corners = mesh.corner_vertices().data();
  resize_for_overwrite(out.faces, mesh.num_faces());
  RangeIds degenerate;
  parallel_for(mesh.num_faces(), threads, [&](Index begin, Index end) {
    std::vector<Index> local;
    for (Index f = begin; f < end; ++f) {
      const Vec3 n = unit_face_normal(p, corners, offsets[f], offsets[f + 1]);
      out.faces[f] = n;
      write(f, n);
      if (n == Vec3(0.0)) local.push_back(f);
    }
    degenerate.add(begin, std::move(local));
  });
  degenerate.write(out.degenerate_faces);
}

// Each vertex gathers its fan's face normals in corner order, which is face order: the sums of the
// one-thread pass, which adds each face to its vertices in face order, bit for bit.
template <class Write>
void vertex_normals_on(const Mesh& mesh, Normals& out, int threads, const Write& write) {
  const Index* fan_offsets = mesh.fan_corner_offsets().data();
  const Index* fan = mesh.fan_corners().data();
  const Index* corner_faces = mesh.corner_faces().data();
  const signed char* signs = mesh.corner_signs().data();
  const Vec3* faces = out.faces.data();
  RangeIds degenerate;
  parallel_for(mesh.num_vertices(), threads, [&](Index begin, Index end) {
    std::vector<Index> local, sorted;
    for (Index v = begin; v < end; ++v) {
      std::span<const Index> in_order(fan + fan_offsets[v], fan + fan_offsets[v + 1]);
      if (!std::is_sorted(in_order.begin(), in_order.end())) {
        sorted.assign(in_order.begin(), in_order.end());
        std::sort(sorted.begin(), sorted.end());
        in_order = sorted;
      }
      Vec3 sum(0.0);
      for (Index c : in_order) {
        const Vec3& n = faces[corner_faces[c]];
        if (n == Vec3(0.0)) continue;  // a degenerate face adds nothing
        if (signs[c] > 0)
          sum += n;
        else
          sum -= n;
      }
      const double len = glm::length(sum);
      if (len > 1e-12) {
        write(v, sum * (1.0 / len));
      } else {
        write(v, Vec3(0.0));
        if (!in_order.empty()) local.push_back(v);
      }
    }
    degenerate.add(begin, std::move(local));
  });
  degenerate.write(out.degenerate_vertices);
}

}  // namespace

void compute_normals(const Mesh& mesh, Normals& out, int threads) {
  if (threads <= 1) return compute_normals(mesh, out);
  face_normals_on(mesh, out, threads, [](Index, const Vec3&) {});
  resize_for_overwrite(out.vertices, mesh.num_vertices());
  vertex_normals_on(mesh, out, threads, [&](Index v, const Vec3& n) { out.vertices[v] = n; });
}

void compute_float_normals(const Mesh& mesh, Normals& scratch, Buffer<glm::vec3>& faces,
                           Buffer<glm::vec3>& vertices, int threads) {
  resize_for_overwrite(faces, mesh.num_faces());
  face_normals_on(mesh, scratch, threads, [&](Index f, const Vec3& n) { faces[f] = glm::vec3(n); });
  resize_for_overwrite(vertices, mesh.num_vertices());
  vertex_normals_on(mesh, scratch, threads, [&](Index v, const Vec3& n) { vertices[v] = glm::vec3(n); });
}

}  // namespace nome
