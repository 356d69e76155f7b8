#pragma once

#include <string>
#include <vector>

#include "nome/query/border_lookup.hpp"

namespace nome::viewer {

enum class SelectionMode { vertex, face, border, border_partial, edge, instance };

const char* to_string(SelectionMode mode);

// What the user has picked on the displayed mesh (report 7.3.2), in click order: the order of selected
// vertices is the corner order of the polygon they add, and the first vertex of a whole border is the
// zipper's matching point. Clicking a selected element again deselects it. Ids refer to the displayed
// mesh; the viewer clears the selection when that mesh's topology changes.
class Selection {
 public:
  SelectionMode mode() const { return mode_; }
  // Changing the mode drops a half-made partial border, keeps everything selected.
  void set_mode(SelectionMode mode);

  void click_vertex(Index v);
  void click_face(Index f);
  void click_edge(Index e);
  // Instance mode (report 8.4): a click on a face selects the instance that placed it, by path.
  void click_instance(const std::string& path);
  // Border modes act on border vertices only; returns a hint for the status bar when the click did
  // nothing or needs a follow-up ("pick the other end").
  std::string click_border_vertex(const BorderLookup& borders, Index v);

  void clear();
  bool is_empty() const {
    return vertices_.empty() && faces_.empty() && edges_.empty() && borders_.empty() && pending_.empty() &&
           instances_.empty();
  }

  const std::vector<Index>& vertices() const { return vertices_; }
  const std::vector<Index>& faces() const { return faces_; }
  const std::vector<Index>& edges() const { return edges_; }
  const std::vector<std::string>& instances() const { return instances_; }
  // Whole loops (closed, from the clicked vertex) and partial segments (open, end to end).
  struct Border {
    std::vector<Index> vertices;
    bool is_loop = false;
  };
  const std::vector<Border>& borders() const { return borders_; }
  // The ends clicked so far of a partial border being made.
  const std::vector<Index>& pending_ends() const { return pending_; }

 private:
  std::string click_partial(const BorderLookup& borders, Index v);

  SelectionMode mode_ = SelectionMode::vertex;
  std::vector<Index> vertices_;
  std::vector<Index> faces_;
  std::vector<Index> edges_;
  std::vector<Border> borders_;
  std::vector<Index> pending_;
  std::vector<std::string> instances_;
};

}  // namespace nome::viewer
