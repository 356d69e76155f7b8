#include "viewer/view/selection.hpp"

#include <algorithm>

namespace nome::viewer {
namespace {

template <typename T>
bool toggle(std::vector<T>& items, const T& item) {
  const auto it = std::find(items.begin(), items.end(), item);
  if (it != items.end()) {
    items.erase(it);
    return false;
  }
  items.push_back(item);
  return true;
}

}  // namespace

const char* to_string(SelectionMode mode) {
  switch (mode) {
    case SelectionMode::vertex:
      return "vertex";
    case SelectionMode::face:
      return "face";
    case SelectionMode::border:
      return "border";
    case SelectionMode::border_partial:
      return "border-partial";
    case SelectionMode::edge:
      return "edge";
    case SelectionMode::instance:
      return "instance";
  }
  return "vertex";
}

void Selection::set_mode(SelectionMode mode) {
  mode_ = mode;
  pending_.clear();
}

void Selection::click_vertex(Index v) {
  toggle(vertices_, v);
}

void Selection::click_face(Index f) {
  toggle(faces_, f);
}

void Selection::click_edge(Index e) {
  toggle(edges_, e);
}

void Selection::click_instance(const std::string& path) {
  toggle(instances_, path);
}

void Selection::clear() {
  vertices_.clear();
  faces_.clear();
  edges_.clear();
  borders_.clear();
  pending_.clear();
  instances_.clear();
}

std::string Selection::click_border_vertex(const BorderLookup& lookup, Index v) {
  if (!lookup.is_on_border(v)) return "not a border vertex: border selection picks vertices on a border";
  // A click on a selected border (whole or partial) deselects it.
  for (auto it = borders_.begin(); it != borders_.end(); ++it) {
    if (std::find(it->vertices.begin(), it->vertices.end(), v) != it->vertices.end()) {
      borders_.erase(it);
      pending_.clear();
      return "border deselected";
    }
  }
  if (mode_ == SelectionMode::border) {
    borders_.push_back({lookup.whole_loop_from(v), lookup.is_closed(lookup.loop_of(v))});
    return {};
  }
  return click_partial(lookup, v);
}

std::string Selection::click_partial(const BorderLookup& lookup, Index v) {
  if (!pending_.empty() && lookup.loop_of(pending_[0]) != lookup.loop_of(v))
    return "the ends of a partial border must lie on the same border";
  if (std::find(pending_.begin(), pending_.end(), v) != pending_.end()) {
    pending_.clear();
    return "partial border cancelled";
  }
  pending_.push_back(v);
  if (pending_.size() == 1) return "partial border: pick the other end";
  if (pending_.size() == 2) {
    // Neighbouring ends leave no choice of side (report 7.3.2).
    if (!lookup.are_adjacent(pending_[0], pending_[1]))
      return "partial border: pick a vertex on the side to keep";
    // An open rim line has one path between two of its vertices.
    const bool is_open = !lookup.is_closed(lookup.loop_of(pending_[0]));
    borders_.push_back({is_open ? *lookup.segment(pending_[0], pending_[1], no_index)
                                : std::vector<Index>{pending_[0], pending_[1]},
                        false});
    pending_.clear();
    return {};
  }
  auto segment = lookup.segment(pending_[0], pending_[1], pending_[2]);
  pending_.clear();
  if (!segment) return "partial border: the three vertices must be distinct vertices of one border";
  borders_.push_back({std::move(*segment), false});
  return {};
}

}  // namespace nome::viewer
