// The instance tree expanded into placements: counted against the instance budget before anything is
// expanded, then walked from the top-level instances through their groups.
#include <algorithm>
#include <cstdio>

#include "nome/scene/scene.hpp"
#include "nome/scene/statement_kinds.hpp"

namespace nome::scene {
namespace {

// Instances are expanded recursively; a deeper hierarchy (no real scene has one) would overflow the stack.
constexpr size_t max_instance_depth = 256;

// A statement inside a group is met once per placement of the group, 2^40 times in a doubling chain:
// its error is reported (and its message, with the names it suggests, made) the first time only.
bool is_reported(const std::vector<Diagnostic>& errors, SourceLocation at) {
  return std::any_of(errors.begin(), errors.end(), [&](const Diagnostic& d) { return d.location == at; });
}

}  // namespace

bool Scene::is_group(const Definition& d) const {
  return d.kind != consolidated_kind && !statement_kinds()[d.kind].makes_geometry();
}

const InstanceDecl* Scene::statement(const Placement& p) const {
  if (p.statement == no_index) return nullptr;
  return p.group == no_index ? &ast_.instances[p.statement] : &ast_.groups[p.group].instances[p.statement];
}

void Scene::expand_roots(std::vector<Diagnostic>& errors) {
  // An unknown name fails the scene: found first, each group read once, since expanding would meet a
  // statement inside a group once per placement of the group (2^17 times in a doubling chain of 17).
  if (reports_unknown_targets(errors)) return;
  // The whole tree is counted before any of it is expanded, so that refusing it costs nothing.
  const std::vector<double> group_sizes = group_expansion_sizes();
  double placements = 0;
  for (Index i = 0; i < ast_.instances.size(); ++i) {
    const InstanceDecl& decl = ast_.instances[i];
    const auto target = definitions_.find(decl.target.text);
    placements += 1;
    if (target != definitions_.end() && is_group(target->second))
      placements += group_sizes[target->second.index];
    if (!within_instance_budget(placements, decl, errors)) return;
    std::vector<Index> stack;
    instances_.push_back({decl.name.text, {}, 0, 0});
    expand(decl, no_index, i, no_index, Index(instances_.size() - 1), stack, errors);
  }
  if (options_.shows_edits && !ast_.consolidated_faces.empty()) {
    // The consolidated mesh is shown where it was made, like the 2016 program did.
    Placement p;
    p.path = consolidated_mesh_name;
    p.top = Index(instances_.size());
    p.target = {consolidated_kind, 0};
    instances_.push_back({consolidated_mesh_name, {}, 0, 0});
    placements_.push_back(std::move(p));
  }
}

void Scene::report_unknown_target(const InstanceDecl& decl, std::vector<Diagnostic>& errors) const {
  if (is_reported(errors, decl.target.location)) return;
  std::vector<std::string> names;
  for (const auto& [name, d] : definitions_) names.push_back(name);
  std::sort(names.begin(), names.end());
  std::string message = "unknown name '" + decl.target.text + "' to instantiate";
  if (points_.count(decl.target.text))
    message = "'" + decl.target.text +
              "' is a point: instantiate a mesh, "
              "face, object, polyline, generator or group";
  else
    message += did_you_mean(decl.target.text, names);
  errors.push_back(located(decl.target.location, message));
}

bool Scene::reports_unknown_targets(std::vector<Diagnostic>& errors) const {
  const size_t before = errors.size();
  std::vector<char> is_read(ast_.groups.size(), 0);
  std::vector<std::pair<Index, Index>> stack;  // a group and its next instance statement, as expand recurses
  const auto visit = [&](const InstanceDecl& decl) {
    const auto it = definitions_.find(decl.target.text);
    if (it == definitions_.end()) return report_unknown_target(decl, errors);
    if (!is_group(it->second) || is_read[it->second.index]) return;
    is_read[it->second.index] = 1;
    stack.push_back({it->second.index, 0});
  };
  for (const InstanceDecl& root : ast_.instances) {
    visit(root);
    while (!stack.empty()) {
      const auto [group, next] = stack.back();
      const std::vector<InstanceDecl>& statements = ast_.groups[group].instances;
      if (next == statements.size()) {
        stack.pop_back();
        continue;
      }
      ++stack.back().second;
      visit(statements[next]);
    }
  }
  return errors.size() > before;
}

void Scene::expand(const InstanceDecl& decl, Index group, Index statement, Index parent, Index top,
                   std::vector<Index>& stack, std::vector<Diagnostic>& errors) {
  const auto it = definitions_.find(decl.target.text);
  if (it == definitions_.end()) return report_unknown_target(decl, errors);
  Placement p;
  p.path = parent == no_index ? decl.name.text : placements_[parent].path + "_" + decl.name.text;
  p.parent = parent;
  p.top = top;
  p.group = group;
  p.statement = statement;
  p.target = it->second;
  const Index id = Index(placements_.size());
  placements_.push_back(std::move(p));
  if (!is_group(it->second)) return;
  const Index g = it->second.index;
  if (std::find(stack.begin(), stack.end(), g) != stack.end()) {
    if (!is_reported(errors, decl.target.location))
      errors.push_back(located(decl.target.location, "group '" + decl.target.text + "' contains itself"));
    return;
  }
  if (stack.size() >= max_instance_depth) {
    if (!is_reported(errors, decl.location))
      errors.push_back(located(decl.location, "instances nested more than " +
                                                  std::to_string(max_instance_depth) + " levels deep"));
    return;
  }
  expand_group(g, id, top, stack, errors);
}

void Scene::expand_group(Index group, Index placement, Index top, std::vector<Index>& stack,
                         std::vector<Diagnostic>& errors) {
  stack.push_back(group);
  // Its instance names are unique: define_names renamed the repeats.
  const GroupDecl& gd = ast_.groups[group];
  for (Index i = 0; i < gd.instances.size(); ++i)
    expand(gd.instances[i], group, i, placement, top, stack, errors);
  stack.pop_back();
}

// Counted without recursion: a chain of groups may be far deeper than the stack allows (expand refuses
// it later). A group on a cycle counts what it reaches before the cycle, which expand reports.
std::vector<double> Scene::group_expansion_sizes() const {
  const size_t groups = ast_.groups.size();
  std::vector<double> size(groups, 0);
  std::vector<char> state(groups, 0);          // 0: not reached, 1: being counted, 2: counted
  std::vector<std::pair<Index, Index>> stack;  // a group and its next instance statement
  const auto group_target = [&](const InstanceDecl& decl) {
    const auto it = definitions_.find(decl.target.text);
    return it != definitions_.end() && is_group(it->second) ? it->second.index : no_index;
  };
  for (Index root = 0; root < groups; ++root) {
    if (state[root]) continue;
    state[root] = 1;
    stack.push_back({root, 0});
    while (!stack.empty()) {
      const auto [g, next] = stack.back();
      const std::vector<InstanceDecl>& statements = ast_.groups[g].instances;
      if (next == statements.size()) {
        state[g] = 2;
        stack.pop_back();
        if (!stack.empty()) size[stack.back().first] += size[g];
        continue;
      }
      ++stack.back().second;
      size[g] += 1;
      const Index target = group_target(statements[next]);
      if (target == no_index || state[target] == 1) continue;
      if (state[target] == 2) {
        size[g] += size[target];
      } else {
        state[target] = 1;
        stack.push_back({target, 0});
      }
    }
  }
  return size;
}

bool Scene::within_instance_budget(double placements, const InstanceDecl& crossing,
                                   std::vector<Diagnostic>& errors) const {
  const double budget = double(options_.instance_budget);
  // Placements are numbered by 32-bit ids.
  const double id_limit = double(no_index) - 1;
  if (placements <= (options_.force ? id_limit : std::min(budget, id_limit))) return true;
  char count[32];
  std::snprintf(count, sizeof count, placements < 1e15 ? "%.0f" : "%.3g", placements);
  const std::string expands = std::string("the scene would expand to about ") + count + " instances";
  if (options_.force || budget >= id_limit) {
    errors.push_back(located(crossing.location, expands + ", more than Nome can number"));
    return false;
  }
  throw BudgetError(
      located(crossing.location, expands + ", over the budget of " + std::to_string(options_.instance_budget))
          .to_string());
}

}  // namespace nome::scene
