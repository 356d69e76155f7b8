#include "nome/mesh/face_orientation.hpp"

namespace nome {
namespace {

// Union-find over faces in which each face also holds its orientation relative to its parent (1 when
// opposite). Roots are the smallest face of their set, so a component's root is its first face.
class OrientationForest {
 public:
  explicit OrientationForest(Index n) : parent_(n), flipped_(n, 0) {
    for (Index f = 0; f < n; ++f) parent_[f] = f;
  }

  // The root of f and f's orientation relative to it. Hangs every face of the path on the root.
  std::pair<Index, char> find(Index f) {
    Index root = f;
    char total = 0;
    while (parent_[root] != root) {
      total ^= flipped_[root];
      root = parent_[root];
    }
    char relative = total;  // of x to the root
    for (Index x = f; x != root;) {
      const Index next = parent_[x];
      const char to_next = flipped_[x];
      parent_[x] = root;
      flipped_[x] = relative;
      relative ^= to_next;
      x = next;
    }
    return {root, total};
  }

  // Records that g is oriented as f (`opposite` false) or against it; false when that contradicts
  // what is already known.
  bool join(Index f, Index g, bool opposite) {
    const auto [rf, pf] = find(f);
    const auto [rg, pg] = find(g);
    const char relation = static_cast<char>(pf ^ pg ^ (opposite ? 1 : 0));
    if (rf == rg) return relation == 0;
    const Index low = rf < rg ? rf : rg, high = rf < rg ? rg : rf;
    parent_[high] = low;
    flipped_[high] = relation;
    return true;
  }

 private:
  std::vector<Index> parent_;
  std::vector<char> flipped_;
};

}  // namespace

// A union-find over the edges in their order rather than a walk from face to face: the edge records are
// read in sequence and neighbouring faces have nearby numbers, where a walk's queue jumps around the mesh.
FaceOrientation face_orientation(const Mesh& mesh) {
  FaceOrientation out;
  out.component_orientable.assign(mesh.num_components(), 1);
  OrientationForest forest(mesh.num_faces());
  for (const Edge& e : mesh.edges()) {
    if (e.is_boundary()) continue;
    if (!forest.join(e.faces[0], e.faces[1], e.is_mobius))
      out.component_orientable[mesh.face_component(e.faces[0])] = 0;
  }
  out.face_signs.resize(mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f)
    out.face_signs[f] = static_cast<signed char>(forest.find(f).second ? -1 : 1);
  return out;
}

}  // namespace nome
