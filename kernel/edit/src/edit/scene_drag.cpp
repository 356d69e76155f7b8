#include "nome/edit/scene_drag.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include <glm/matrix.hpp>

#include "nome/error.hpp"
#include "nome/scene/source_text.hpp"

namespace nome {
namespace {

// A coordinate as the text writes its numbers: six decimals at most (the rounding moves a vertex by far
// less than anything a screen shows), trailing zeros dropped down to the decimals the number had.
std::string coordinate_text(double x, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6f", std::round(x * 1e6) / 1e6);
  std::string out = text;
  const std::size_t point = out.find('.');
  const std::size_t keep = decimals > 0 ? point + 1 + std::size_t(std::min(decimals, 6)) : point;
  while (out.size() > keep && (out.back() == '0' || out.back() == '.')) out.pop_back();
  if (out.size() == keep && keep == point + 1) out.pop_back();
  if (out.starts_with('-') && out.find_first_not_of("-0.") == std::string::npos) out.erase(0, 1);
  return out;
}

// A slider value on its step, in its range, without the step's binary fraction noise (-1.5 + 7 * 0.1).
double on_step(double value, double min, double max, double step) {
  if (step > 0) {
    value = min + std::round((value - min) / step) * step;
    if (value > max + step * 1e-9) value -= step;
    value = std::round(value * 1e9) / 1e9;
  }
  return std::clamp(value, min, max);
}

// Solves the k x k system a x = b (a symmetric positive definite after damping) by elimination with
// partial pivoting; false when it is singular.
bool solve_linear(std::vector<double> a, std::vector<double> b, std::vector<double>& x) {
  const std::size_t k = b.size();
  for (std::size_t c = 0; c < k; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < k; ++r)
      if (std::abs(a[r * k + c]) > std::abs(a[pivot * k + c])) pivot = r;
    if (std::abs(a[pivot * k + c]) < 1e-300) return false;
    for (std::size_t j = 0; j < k; ++j) std::swap(a[c * k + j], a[pivot * k + j]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < k; ++r) {
      const double f = a[r * k + c] / a[c * k + c];
      for (std::size_t j = c; j < k; ++j) a[r * k + j] -= f * a[c * k + j];
      b[r] -= f * b[c];
    }
  }
  x.assign(k, 0.0);
  for (std::size_t c = k; c-- > 0;) {
    double s = b[c];
    for (std::size_t j = c + 1; j < k; ++j) s -= a[c * k + j] * x[j];
    x[c] = s / a[c * k + c];
  }
  return true;
}

// Where a transform's text ends: after its keyword and its parenthesised groups (a rotate has two).
std::size_t transform_end(std::string_view text, std::size_t at, scene::TransformKind kind) {
  int groups = kind == scene::TransformKind::rotate ? 2 : 1;
  int depth = 0;
  for (std::size_t i = at; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(' || c == '{') ++depth;
    if ((c == ')' || c == '}') && --depth == 0 && c == ')' && --groups == 0) return i + 1;
  }
  return text.size();
}

}  // namespace

std::string replaced_text(std::string_view text, const std::vector<TextReplacement>& replacements) {
  std::string out;
  std::size_t at = 0;
  for (const TextReplacement& r : replacements) {
    out.append(text.substr(at, r.begin - at));
    out += r.text;
    at = r.end;
  }
  out.append(text.substr(at));
  return out;
}

SceneDrag::SceneDrag(const scene::Scene& scene, std::string text, const DragSelection& selection)
    : text_(std::move(text)), file_(scene.file()) {
  if (selection.vertices.empty() && selection.instances.empty())
    throw InvalidInputError("drag: nothing is selected (select vertices or instances first)");
  for (const std::string& name : selection.vertices) add_vertex(scene, name);
  for (const std::string& path : selection.instances) add_instance(scene, path);
  if (!slider_vertices_.empty()) {
    probe_.emplace(scene);
    for (const SliderVertex& v : slider_vertices_) placed_.push_back(v.vertex);
    std::sort(candidate_sliders_.begin(), candidate_sliders_.end());
    candidate_sliders_.erase(std::unique(candidate_sliders_.begin(), candidate_sliders_.end()),
                             candidate_sliders_.end());
    choose_sliders(candidate_sliders_);
  }
  std::vector<Vec3> at;
  for (const LiteralPoint& p : points_) at.push_back(p.start_world);
  for (const SliderVertex& v : slider_vertices_) at.push_back(v.start);
  for (const MovedInstance& i : instances_) at.push_back(i.centre);
  for (const Vec3& p : at) centre_ += p / double(at.size());
}

SceneDrag::NumberToken SceneDrag::number_token(const scene::Value& value, const std::string& what) const {
  const std::size_t begin = scene::byte_offset(text_, value.location);
  std::size_t end = begin;
  while (end < text_.size() &&
         (std::isdigit(static_cast<unsigned char>(text_[end])) || text_[end] == '.' || text_[end] == '-' ||
          text_[end] == '+' || text_[end] == 'e' || text_[end] == 'E'))
    ++end;
  const std::string token = text_.substr(begin, end - begin);
  char* parsed_end = nullptr;
  const double read = std::strtod(token.c_str(), &parsed_end);
  if (token.empty() || parsed_end != token.c_str() + token.size() ||
      std::abs(read - value.literal) > 1e-9 * std::max(1.0, std::abs(value.literal)))
    throw InvalidInputError("drag: " + what + ": its numbers are not at " + file_ + ":" +
                            std::to_string(value.location.line) + ":" +
                            std::to_string(value.location.column) +
                            " of the text (apply or revert the text's changes first)");
  const std::size_t point = token.find('.');
  const std::size_t exponent = token.find_first_of("eE");
  const int decimals =
      point == std::string::npos || exponent != std::string::npos ? 0 : int(token.size() - point - 1);
  return {begin, end, decimals};
}

void SceneDrag::add_vertex(const scene::Scene& scene, const std::string& name) {
  const scene::VertexOrigin origin = scene.vertex_origin(name);
  const std::string place =
      file_ + ":" + std::to_string(origin.statement.line) + ":" + std::to_string(origin.statement.column);
  if (origin.point) {
    const scene::PointDecl& point = scene.ast().points[*origin.point];
    const bool is_literal = std::all_of(std::begin(point.xyz), std::end(point.xyz),
                                        [](const scene::Value& v) { return v.expr == no_index; });
    if (is_literal && std::abs(glm::determinant(origin.point_to_world)) > 1e-12) {
      for (const LiteralPoint& p : points_)
        if (p.name == point.name.text) return;  // the same point through another vertex: it moves once
      LiteralPoint p;
      for (int k = 0; k < 3; ++k) p.tokens[k] = number_token(point.xyz[k], "point '" + point.name.text + "'");
      p.start_world = origin.position;
      p.world_to_point = glm::inverse(origin.point_to_world);
      p.name = point.name.text;
      points_.push_back(p);
      return;
    }
  }
  if (origin.parameters.empty()) {
    const std::string why = origin.point
                                ? " gives its coordinates as expressions that read no slider"
                                : " makes it from numbers that are not its coordinates, and reads no slider";
    throw InvalidInputError("drag: vertex '" + name + "' cannot move: " + origin.statement_text + " (" +
                            place + ")" + why + "; write its coordinates as numbers or give them a slider");
  }
  slider_vertices_.push_back(
      {*scene.find_placed_vertex(name), origin.position, origin.statement_text + " (" + place + ")"});
  slider_vertex_names_.push_back(name);
  for (const scene::ParameterId p : origin.parameters)
    if (p.index() < scene.parameters().size()) candidate_sliders_.push_back(p);
}

void SceneDrag::add_instance(const scene::Scene& scene, const std::string& path) {
  const scene::InstanceOrigin origin = scene.instance_origin(path);
  for (const MovedInstance& i : instances_)
    if (i.group == origin.group && i.statement == origin.statement) return;  // one statement, moved once
  const scene::InstanceDecl& decl = scene.instance_statement(origin);
  MovedInstance moved;
  moved.path = path;
  moved.group = origin.group;
  moved.statement = origin.statement;
  moved.centre = origin.position;
  std::size_t last = decl.transforms.size();
  for (std::size_t i = decl.transforms.size(); i-- > 0;) {
    const scene::TransformDecl& t = decl.transforms[i];
    if (t.kind == scene::TransformKind::translate &&
        std::all_of(t.args, t.args + 3, [](const scene::Value& v) { return v.expr == no_index; })) {
      last = i;
      break;
    }
  }
  // A change t of the translate at `last` moves the instance by parent * (transforms after it) * t.
  const glm::dmat3 parent(origin.parent_to_world);
  glm::dmat3 to_world = parent;
  if (last < decl.transforms.size()) {
    to_world = parent * glm::dmat3(scene.transforms_matrix(decl, last + 1, decl.transforms.size()));
    const scene::TransformDecl& t = decl.transforms[last];
    for (int k = 0; k < 3; ++k) {
      moved.translate.push_back(number_token(t.args[k], "instance '" + path + "'"));
      moved.start_translate[k] = t.args[k].literal;
    }
  } else if (decl.transforms.empty()) {
    moved.insert_at = scene::byte_offset(text_, decl.target.location) + decl.target.text.size();
  } else {
    const scene::TransformDecl& t = decl.transforms.back();
    moved.insert_at = transform_end(text_, scene::byte_offset(text_, t.location), t.kind);
  }
  if (std::abs(glm::determinant(to_world)) < 1e-12)
    throw InvalidInputError("drag: instance '" + path + "' cannot move: its transforms flatten it");
  moved.world_to_translate = glm::inverse(to_world);
  instances_.push_back(std::move(moved));
}

void SceneDrag::choose_sliders(const std::vector<scene::ParameterId>& candidates) {
  const std::vector<Vec3> start = positions_at({});
  for (const scene::ParameterId id : candidates) {
    const scene::Parameter& p = probe_->parameters()[id];
    if (!(p.max > p.min)) continue;
    const double h = p.step > 0 ? p.step : (p.max - p.min) / 100;
    const double trial = p.value + h <= p.max ? p.value + h : p.value - h;
    const double value = p.value;
    bool keeps_faces = false, moves = false;
    try {
      probe_->set_parameter(id, trial);
      keeps_faces = probe_->last_change_moved_vertices_only();
      if (keeps_faces) moves = positions_at({}) != start;
      probe_->set_parameter(id, value);
    } catch (const Error&) {
      continue;  // a value the scene refuses: not a slider to drag with
    }
    if (keeps_faces && moves) sliders_.push_back({id, value, p.min, p.max, p.step, p.full_name});
  }
  const std::vector<double> starts = [&] {
    std::vector<double> v;
    for (const Slider& s : sliders_) v.push_back(s.start);
    return v;
  }();
  // Each slider vertex must move with one of them, or the drag cannot place it.
  for (std::size_t i = 0; i < slider_vertices_.size(); ++i) {
    bool moves = false;
    for (std::size_t j = 0; j < sliders_.size() && !moves; ++j) {
      std::vector<double> trial = starts;
      const Slider& s = sliders_[j];
      trial[j] = s.start + (s.step > 0 ? s.step : (s.max - s.min) / 100) * (s.start < s.max ? 1 : -1);
      moves = positions_at(trial)[i] != start[i];
    }
    if (!moves)
      throw InvalidInputError("drag: vertex '" + slider_vertex_names_[i] +
                              "' cannot move: " + slider_vertices_[i].statement +
                              " places it from numbers that are not its coordinates, and no slider it reads "
                              "moves it without changing its faces");
  }
}

std::vector<Vec3> SceneDrag::positions_at(const std::vector<double>& values) {
  std::vector<std::pair<scene::ParameterId, double>> trial;
  for (std::size_t j = 0; j < values.size(); ++j) trial.push_back({sliders_[j].id, values[j]});
  return probe_->positions_with(placed_, trial);
}

double SceneDrag::miss(const std::vector<double>& values, const std::vector<Vec3>& targets) {
  double sum = 0;
  try {
    const std::vector<Vec3> at = positions_at(values);
    for (std::size_t i = 0; i < at.size(); ++i) sum += glm::dot(at[i] - targets[i], at[i] - targets[i]);
  } catch (const Error&) {
    return std::numeric_limits<double>::infinity();
  }
  return std::isfinite(sum) ? sum : std::numeric_limits<double>::infinity();
}

double SceneDrag::relax(std::vector<double>& x, const std::vector<bool>& fixed,
                        const std::vector<Vec3>& targets) {
  const std::size_t k = sliders_.size(), m = 3 * targets.size();
  double cost = miss(x, targets);
  // Levenberg-Marquardt over the sliders not fixed, each kept in its range (a slider at an end that the
  // descent pushes past it is held there for the iteration); derivatives by differences of the
  // positions-only evaluation.
  double damping = 1e-3;
  for (int iteration = 0; iteration < 50 && cost > 1e-24; ++iteration) {
    std::vector<bool> held = fixed;
    if (std::all_of(held.begin(), held.end(), [](bool b) { return b; })) break;
    const std::vector<Vec3> at = positions_at(x);
    std::vector<double> jacobian(m * k, 0.0);
    for (std::size_t j = 0; j < k; ++j) {
      if (held[j]) continue;
      const Slider& s = sliders_[j];
      double h = 1e-6 * std::max(1.0, s.max - s.min);
      if (x[j] + h > s.max) h = -h;
      std::vector<double> trial = x;
      trial[j] += h;
      const std::vector<Vec3> moved = positions_at(trial);
      for (std::size_t i = 0; i < targets.size(); ++i)
        for (int c = 0; c < 3; ++c) jacobian[(3 * i + c) * k + j] = (moved[i][c] - at[i][c]) / h;
    }
    std::vector<double> normal(k * k, 0.0), descent(k, 0.0);
    for (std::size_t r = 0; r < m; ++r) {
      const double residual = at[r / 3][int(r % 3)] - targets[r / 3][int(r % 3)];
      for (std::size_t a = 0; a < k; ++a) {
        descent[a] -= jacobian[r * k + a] * residual;
        for (std::size_t b = 0; b < k; ++b) normal[a * k + b] += jacobian[r * k + a] * jacobian[r * k + b];
      }
    }
    for (std::size_t j = 0; j < k; ++j) {
      const Slider& s = sliders_[j];
      held[j] = held[j] || (x[j] <= s.min && descent[j] < 0) || (x[j] >= s.max && descent[j] > 0);
      if (!held[j]) continue;
      for (std::size_t a = 0; a < k; ++a) normal[a * k + j] = normal[j * k + a] = 0.0;
      normal[j * k + j] = 1.0;
      descent[j] = 0.0;
    }
    bool improved = false;
    const double cost_before = cost;
    for (int attempt = 0; attempt < 8 && !improved; ++attempt) {
      std::vector<double> damped = normal, dx;
      for (std::size_t a = 0; a < k; ++a) damped[a * k + a] += damping * normal[a * k + a] + 1e-12;
      if (!solve_linear(damped, descent, dx)) break;
      std::vector<double> trial = x;
      for (std::size_t j = 0; j < k; ++j)
        if (!held[j]) trial[j] = std::clamp(x[j] + dx[j], sliders_[j].min, sliders_[j].max);
      if (trial == x) break;  // nowhere left to go within the ranges
      const double trial_cost = miss(trial, targets);
      if (trial_cost < cost) {
        x = trial;
        cost = trial_cost;
        damping = std::max(damping / 10, 1e-12);
        improved = true;
      } else {
        damping *= 10;
      }
    }
    // Converged: another iteration would gain less than rounding does.
    if (!improved || cost_before - cost <= 1e-9 * cost_before) break;
  }
  return cost;
}

void SceneDrag::search_steps(std::vector<double> x, std::vector<bool> fixed, const std::vector<Vec3>& targets,
                             Search& search) {
  // The next slider with a step to put on it: the two steps around its relaxed value, each with the others
  // relaxed again; a branch whose relaxed miss is no better than the best found is left (the relaxation
  // is a bound as far as the local solve finds the least miss).
  std::size_t j = 0;
  while (j < sliders_.size() && (fixed[j] || !(sliders_[j].step > 0))) ++j;
  if (j == sliders_.size()) {
    const double cost = miss(x, targets);
    if (cost < search.best_cost) {
      search.best_cost = cost;
      search.best = x;
    }
    return;
  }
  const Slider& s = sliders_[j];
  const double below = on_step(s.min + std::floor((x[j] - s.min) / s.step) * s.step, s.min, s.max, s.step);
  const double above = on_step(below + s.step, s.min, s.max, s.step);
  std::vector<double> choices{below};
  if (above != below) choices.push_back(above);
  if (choices.size() == 2 && std::abs(above - x[j]) < std::abs(below - x[j]))
    std::swap(choices[0], choices[1]);
  fixed[j] = true;
  for (const double choice : choices) {
    if (search.best_cost <= 1e-24 || search.budget == 0) return;
    --search.budget;
    std::vector<double> y = x;
    y[j] = choice;
    if (relax(y, fixed, targets) < search.best_cost) search_steps(y, fixed, targets, search);
  }
}

std::vector<double> SceneDrag::solve_sliders(const std::vector<Vec3>& targets) {
  const std::size_t k = sliders_.size();
  std::vector<double> x;
  for (const Slider& s : sliders_) x.push_back(s.start);
  const double relaxed = relax(x, std::vector<bool>(k, false), targets);
  // The relaxed values put on their steps are the first answer; a search over the steps around them, each
  // slider put on one with the others relaxed again, looks for a closer one.
  Search search;
  search.best = x;
  for (std::size_t j = 0; j < k; ++j)
    search.best[j] = on_step(x[j], sliders_[j].min, sliders_[j].max, sliders_[j].step);
  search.best_cost = miss(search.best, targets);
  // The relaxed miss bounds every answer on the steps: one as close needs no search.
  if (search.best_cost > relaxed * (1 + 1e-9) + 1e-24)
    search_steps(x, std::vector<bool>(k, false), targets, search);
  x = search.best;
  double cost = search.best_cost;
  // Then a step of one slider or of two at once while that lands closer.
  const auto stepped = [&](std::vector<double> values, std::size_t j, double direction) {
    const Slider& s = sliders_[j];
    values[j] = on_step(values[j] + direction * s.step, s.min, s.max, s.step);
    return values;
  };
  const auto try_values = [&](const std::vector<double>& trial) {
    if (trial == x) return false;
    const double trial_cost = miss(trial, targets);
    if (!(trial_cost < cost)) return false;
    x = trial;
    cost = trial_cost;
    return true;
  };
  for (int pass = 0; pass < 1000 && cost > 1e-24; ++pass) {
    bool improved = false;
    for (std::size_t j = 0; j < k; ++j)
      if (sliders_[j].step > 0)
        for (const double d : {-1.0, 1.0}) improved = try_values(stepped(x, j, d)) || improved;
    for (std::size_t i = 0; i < k && !improved; ++i)
      for (std::size_t j = i + 1; j < k && !improved; ++j)
        if (sliders_[i].step > 0 && sliders_[j].step > 0)
          for (const double a : {-1.0, 1.0})
            for (const double b : {-1.0, 1.0})
              improved = try_values(stepped(stepped(x, i, a), j, b)) || improved;
    if (!improved) break;
  }
  return x;
}

DragStep SceneDrag::move(const Vec3& offset) {
  DragStep step;
  for (const LiteralPoint& p : points_) {
    const Vec3 local = Vec3(p.world_to_point * glm::dvec4(p.start_world + offset, 1.0));
    for (int k = 0; k < 3; ++k)
      step.replacements.push_back(
          {p.tokens[k].begin, p.tokens[k].end, coordinate_text(local[k], p.tokens[k].decimals)});
  }
  for (const MovedInstance& i : instances_) {
    const Vec3 t = i.start_translate + i.world_to_translate * offset;
    if (!i.translate.empty()) {
      for (int k = 0; k < 3; ++k)
        step.replacements.push_back(
            {i.translate[k].begin, i.translate[k].end, coordinate_text(t[k], i.translate[k].decimals)});
    } else if (offset != Vec3(0.0)) {
      step.replacements.push_back({i.insert_at, i.insert_at,
                                   " translate (" + coordinate_text(t.x, 0) + " " + coordinate_text(t.y, 0) +
                                       " " + coordinate_text(t.z, 0) + ")"});
    }
  }
  std::sort(step.replacements.begin(), step.replacements.end(),
            [](const TextReplacement& a, const TextReplacement& b) { return a.begin < b.begin; });
  if (!sliders_.empty()) {
    std::vector<Vec3> targets;
    for (const SliderVertex& v : slider_vertices_) targets.push_back(v.start + offset);
    const std::vector<double> values = solve_sliders(targets);
    const std::vector<Vec3> at = positions_at(values);
    for (std::size_t j = 0; j < values.size(); ++j) step.sliders.push_back({sliders_[j].id, values[j]});
    for (std::size_t i = 0; i < at.size(); ++i)
      step.slider_miss = std::max(step.slider_miss, glm::distance(at[i], targets[i]));
  }
  return step;
}

std::vector<scene::ParameterId> SceneDrag::sliders() const {
  std::vector<scene::ParameterId> out;
  for (const Slider& s : sliders_) out.push_back(s.id);
  return out;
}

std::string SceneDrag::description() const {
  std::vector<std::string> parts;
  for (const LiteralPoint& p : points_) parts.push_back("the numbers of point '" + p.name + "'");
  if (!sliders_.empty()) {
    std::string names;
    for (const Slider& s : sliders_) names += (names.empty() ? "" : ", ") + s.name;
    parts.push_back((sliders_.size() == 1 ? "slider " : "sliders ") + names);
  }
  for (const MovedInstance& i : instances_)
    parts.push_back((i.translate.empty() ? "a translate for " : "the translate of ") + i.path);
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i)
    out += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  return out;
}

}  // namespace nome
