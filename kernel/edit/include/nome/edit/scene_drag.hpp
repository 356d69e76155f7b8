#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>

#include "nome/mesh/types.hpp"
#include "nome/scene/scene.hpp"

namespace nome {

// A byte range of a text and what replaces it (an insertion when the range is empty).
struct TextReplacement {
  std::size_t begin = 0, end = 0;
  std::string text;
};
// The text with the replacements made (sorted by position, not overlapping).
std::string replaced_text(std::string_view text, const std::vector<TextReplacement>& replacements);

// What a drag moves: placed vertices by full hierarchical name, instances by placement path (`sh_tun1`).
struct DragSelection {
  std::vector<std::string> vertices;
  std::vector<std::string> instances;
};

// Where a drag leaves the scene for one offset: the numbers of the text it rewrites and the slider
// values it moves to.
struct DragStep {
  std::vector<TextReplacement> replacements;  // against SceneDrag::text(), sorted
  std::vector<std::pair<scene::ParameterId, double>> sliders;
  // How far the slider-placed vertices end from where they were dropped (the largest distance): 0 for a
  // reachable drop, more where a slider stopped at its range's end or on its step.
  double slider_miss = 0;
};

// A drag of vertices and instances (sculpting by hand), decided once at the press: each vertex is moved
// the fewest tokens that place it, in this order of preference:
// - a point whose coordinates are written as numbers: those three numbers are rewritten in place (through
//   the inverse of the matrix that places it, so that it lands where it was dropped);
// - a vertex whose position reads sliders: the sliders that keep the faces are solved for (least squares
//   over them, bounded by their ranges, then put on their steps), from the values at the press;
// - an instance: the last translate of its statement written as numbers is changed, or a translate is
//   added after its other transforms.
// A vertex that none of them moves is refused (InvalidInputError naming the statement that places it and
// why). The scene is not changed: each step says what to change, from the state at the press.
class SceneDrag {
 public:
  // `text`: the scene's text as the scene was read from it (its statements' places are located in it).
  SceneDrag(const scene::Scene& scene, std::string text, const DragSelection& selection);

  // What places the selection `offset` (world units) away from where it was at the press.
  DragStep move(const Vec3& offset);

  const std::string& text() const { return text_; }
  // The mean of the dragged vertices' and instances' positions at the press (where a handle stands).
  Vec3 centre() const { return centre_; }
  // What the drag changes: "the numbers of point 'p1'", "sliders fp_ro, fp_z", "the translate of fun1".
  std::string description() const;
  // The sliders it may move.
  std::vector<scene::ParameterId> sliders() const;

 private:
  struct NumberToken {
    std::size_t begin = 0, end = 0;
    int decimals = 0;  // as the text wrote it: a new number keeps at least as many
  };
  struct LiteralPoint {
    NumberToken tokens[3];
    Vec3 start_world{0.0};
    glm::dmat4 world_to_point{1.0};
    std::string name;
  };
  struct SliderVertex {
    scene::PlacedVertex vertex;
    Vec3 start{0.0};
    std::string statement;  // what places it, and where: for the message when no slider moves it
  };
  struct Slider {
    scene::ParameterId id;
    double start = 0, min = 0, max = 0, step = 0;
    std::string name;
  };
  struct MovedInstance {
    std::string path;
    Index group = no_index, statement = no_index;
    Vec3 centre{0.0};
    std::vector<NumberToken> translate;  // its last literal translate's three numbers; empty: none
    Vec3 start_translate{0.0};
    std::size_t insert_at = 0;           // where a new translate goes when there is none
    glm::dmat3 world_to_translate{1.0};  // a world offset as a change of those numbers
  };

  void add_vertex(const scene::Scene& scene, const std::string& name);
  void add_instance(const scene::Scene& scene, const std::string& path);
  // Keeps the sliders that move the slider vertices without changing any face.
  void choose_sliders(const std::vector<scene::ParameterId>& candidates);
  // The slider values that bring the slider vertices closest to their targets, on the sliders' steps.
  std::vector<double> solve_sliders(const std::vector<Vec3>& targets);
  // The least miss over the sliders not `fixed`, from `x` (continuous values); x becomes where it is.
  double relax(std::vector<double>& x, const std::vector<bool>& fixed, const std::vector<Vec3>& targets);
  struct Search {
    std::vector<double> best;
    double best_cost = 0;
    int budget = 16;  // relaxations left
  };
  void search_steps(std::vector<double> x, std::vector<bool> fixed, const std::vector<Vec3>& targets,
                    Search& search);
  double miss(const std::vector<double>& values, const std::vector<Vec3>& targets);
  std::vector<Vec3> positions_at(const std::vector<double>& values);
  NumberToken number_token(const scene::Value& value, const std::string& what) const;

  std::string text_;
  std::string file_;
  std::optional<scene::Scene> probe_;  // evaluates the slider vertices at trial values
  std::vector<LiteralPoint> points_;
  std::vector<SliderVertex> slider_vertices_;
  std::vector<scene::PlacedVertex> placed_;  // the slider vertices'

  std::vector<std::string> slider_vertex_names_;
  std::vector<scene::ParameterId> candidate_sliders_;
  std::vector<Slider> sliders_;
  std::vector<MovedInstance> instances_;
  Vec3 centre_{0.0};
};

}  // namespace nome
