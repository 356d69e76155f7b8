#include "nome/scene/diagnostic.hpp"

#include <algorithm>
#include <numeric>

namespace nome::scene {
namespace {

std::string join_messages(const std::vector<Diagnostic>& errors) {
  std::string out;
  for (const Diagnostic& d : errors) {
    if (!out.empty()) out += "\n";
    out += d.to_string();
  }
  return out;
}

}  // namespace

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), size_t{0});
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string location_text(SourceLocation at) {
  return std::to_string(at.line) + ":" + std::to_string(at.column);
}

std::string Diagnostic::place() const {
  return (file.empty() ? std::string("<input>") : file) + ":" + std::to_string(location.line) + ":" +
         std::to_string(location.column);
}

std::string Diagnostic::to_string() const {
  return place() + ": " + (severity == Severity::warning ? "warning: " : "") + message;
}

void Diagnostics::error(SourceLocation at, std::string message) {
  // A file of garbage would otherwise give an error per byte.
  constexpr size_t max_listed_errors = 20;
  if (errors_ == max_listed_errors)
    items_.push_back({Severity::error, file_, at, "more errors follow from here; fix those above first"});
  if (errors_++ >= max_listed_errors) return;
  items_.push_back({Severity::error, file_, at, std::move(message)});
}

void Diagnostics::warning(SourceLocation at, std::string message) {
  items_.push_back({Severity::warning, file_, at, std::move(message)});
}

void Diagnostics::add(Diagnostic diagnostic) {
  if (diagnostic.severity == Severity::error) ++errors_;
  items_.push_back(std::move(diagnostic));
}

bool Diagnostics::has_errors() const {
  return std::any_of(items_.begin(), items_.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::error; });
}

void Diagnostics::throw_if_errors() const {
  std::vector<Diagnostic> errors;
  for (const Diagnostic& d : items_)
    if (d.severity == Severity::error) errors.push_back(d);
  if (!errors.empty()) throw SceneError(std::move(errors));
}

SceneError::SceneError(std::vector<Diagnostic> errors)
    : Error(join_messages(errors)), errors_(std::move(errors)) {}

std::vector<std::string> nearest_names(const std::string& name, const std::vector<std::string>& candidates,
                                       size_t limit) {
  // Names sharing the final component (the vertex's own name) come first: `fun9_hc3` -> `cf_fun3_hc3`.
  const std::string tail = name.substr(name.rfind('_') == std::string::npos ? 0 : name.rfind('_'));
  std::vector<std::pair<size_t, const std::string*>> scored;
  for (const std::string& c : candidates) {
    // A hierarchical name is compared whole and by its tail as long as the name given.
    size_t d = edit_distance(name, c);
    if (c.size() > name.size()) d = std::min(d, edit_distance(name, c.substr(c.size() - name.size())));
    if (d > std::max<size_t>(1, (name.size() + 1) / 3)) continue;
    if (c.size() < tail.size() || c.compare(c.size() - tail.size(), tail.size(), tail) != 0) d += 1;
    scored.emplace_back(d, &c);
  }
  std::stable_sort(scored.begin(), scored.end(), [](auto& a, auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (auto& [d, c] : scored) {
    if (out.size() == limit) break;
    if (std::find(out.begin(), out.end(), *c) == out.end()) out.push_back(*c);
  }
  return out;
}

std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates) {
  const std::vector<std::string> near = nearest_names(name, candidates);
  if (near.empty()) return "";
  std::string out = " (did you mean ";
  for (size_t i = 0; i < near.size(); ++i) out += (i ? ", " : "") + near[i];
  return out + "?)";
}

}  // namespace nome::scene
