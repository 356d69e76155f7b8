#include "nome/query/border_lookup.hpp"

namespace nome {

BorderLookup::BorderLookup(const Mesh& mesh)
    : loop_of_(mesh.num_vertices(), no_index), position_(mesh.num_vertices(), no_index) {
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l) {
    const auto vertices = mesh.loop_vertices(l);
    for (Index i = 0; i < vertices.size(); ++i) {
      loop_of_[vertices[i]] = l;
      position_[vertices[i]] = i;
      loop_vertices_.push_back(vertices[i]);
    }
    loop_offsets_.push_back(static_cast<Index>(loop_vertices_.size()));
    is_closed_.push_back(1);
  }
}

void BorderLookup::add_rim_lines(const RimLines& rims, Index first_id) {
  const Index end = first_id + rims.num_vertices();
  if (loop_of_.size() < end) {
    loop_of_.resize(end, no_index);
    position_.resize(end, no_index);
  }
  for (Index l = 0; l < rims.num_lines(); ++l) {
    const Index loop = Index(is_closed_.size());
    for (Index v = rims.offsets[l]; v < rims.offsets[l + 1]; ++v) {
      loop_of_[first_id + v] = loop;
      position_[first_id + v] = v - rims.offsets[l];
      loop_vertices_.push_back(first_id + v);
    }
    loop_offsets_.push_back(static_cast<Index>(loop_vertices_.size()));
    is_closed_.push_back(rims.is_closed[l]);
  }
}

std::vector<Index> BorderLookup::whole_loop_from(Index v) const {
  if (!is_on_border(v)) return {};
  const auto loop = loop_vertices(loop_of_[v]);
  if (!is_closed(loop_of_[v])) return {loop.begin(), loop.end()};
  std::vector<Index> out;
  out.reserve(loop.size());
  for (Index i = 0; i < loop.size(); ++i) out.push_back(loop[(position_[v] + i) % loop.size()]);
  return out;
}

bool BorderLookup::are_adjacent(Index a, Index b) const {
  if (!is_on_border(a) || !is_on_border(b) || a == b || loop_of_[a] != loop_of_[b]) return false;
  if (!is_closed(loop_of_[a])) return true;
  const Index n = static_cast<Index>(loop_vertices(loop_of_[a]).size());
  return (position_[a] + 1) % n == position_[b] || (position_[b] + 1) % n == position_[a];
}

std::optional<std::vector<Index>> BorderLookup::segment(Index a, Index b, Index side) const {
  if (!is_on_border(a) || !is_on_border(b) || a == b || loop_of_[a] != loop_of_[b]) return std::nullopt;
  const Index loop = loop_of_[a];
  if (!is_closed(loop)) {
    const auto vertices = loop_vertices(loop);
    std::vector<Index> out;
    const int step = position_[a] < position_[b] ? 1 : -1;
    for (Index i = position_[a];; i = Index(int(i) + step)) {
      out.push_back(vertices[i]);
      if (i == position_[b]) return out;
    }
  }
  if (!is_on_border(side)) return std::nullopt;
  if (loop_of_[b] != loop || loop_of_[side] != loop || a == b || side == a || side == b) return std::nullopt;
  const auto vertices = loop_vertices(loop);
  const Index n = static_cast<Index>(vertices.size());
  // Walk forward from a; if b comes before side, the side lies on the backward walk instead.
  const Index to_b = (position_[b] + n - position_[a]) % n;
  const Index to_side = (position_[side] + n - position_[a]) % n;
  const bool forward = to_side < to_b;
  std::vector<Index> out;
  const Index length = forward ? to_b : n - to_b;
  out.reserve(length + 1);
  for (Index i = 0; i <= length; ++i) {
    const Index step = forward ? position_[a] + i : position_[a] + n - i;
    out.push_back(vertices[step % n]);
  }
  return out;
}

}  // namespace nome
