#include "viewer/panels/parameter_panel.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace nome::viewer {

void ParameterPanelState::track(const scene::Scene& scene) {
  if (file_values.size() == scene.parameters().size()) return;
  file_values.clear();
  for (const scene::Parameter& p : scene.parameters()) file_values.push_back(p.value);
  ranges.clear();
}

bool ParameterPanelState::is_moved(const scene::Parameter& p, scene::ParameterId id) const {
  return file_values.contains(id) && p.value != file_values[id];
}

std::pair<double, double> ParameterPanelState::range(const scene::Parameter& p, scene::ParameterId id) const {
  const auto it = ranges.find(id);
  return it == ranges.end() ? std::pair{p.min, p.max} : it->second;
}

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

}  // namespace

std::vector<scene::ParameterId> filtered_parameters(const scene::Scene& scene, const scene::Bank& bank,
                                                    const std::string& filter) {
  const std::vector<scene::ParameterId>& shown = bank.shown.empty() ? bank.parameters : bank.shown;
  const std::string wanted = lower(filter);
  if (wanted.empty() || lower(bank.name).find(wanted) != std::string::npos) return shown;
  std::vector<scene::ParameterId> kept;
  for (scene::ParameterId id : shown)
    if (lower(scene.parameters()[id].name).find(wanted) != std::string::npos ||
        lower(scene.parameters()[id].label).find(wanted) != std::string::npos)
      kept.push_back(id);
  return kept;
}

bool holds_any(const scene::Bank& bank, const std::vector<scene::ParameterId>& parameters) {
  return std::any_of(bank.parameters.begin(), bank.parameters.end(), [&](scene::ParameterId id) {
    return std::find(parameters.begin(), parameters.end(), id) != parameters.end();
  });
}

std::vector<Index> bank_order(const scene::Scene& scene, const std::vector<scene::ParameterId>& first) {
  std::vector<Index> leading, rest;
  for (Index b = 0; b < scene.banks().size(); ++b)
    (holds_any(scene.banks()[b], first) ? leading : rest).push_back(b);
  leading.insert(leading.end(), rest.begin(), rest.end());
  return leading;
}

std::vector<std::pair<scene::ParameterId, double>> bank_reset(const scene::Scene& scene,
                                                              const scene::Bank& bank,
                                                              const ParameterPanelState& state) {
  std::vector<std::pair<scene::ParameterId, double>> moves;
  for (scene::ParameterId id : bank.parameters)
    if (state.is_moved(scene.parameters()[id], id)) moves.push_back({id, state.file_values[id]});
  return moves;
}

double snap_to_step(const scene::Parameter& p, double value, std::pair<double, double> range) {
  double snapped = value;
  if (p.step > 0.0) snapped = p.min + std::round((value - p.min) / p.step) * p.step;
  return std::clamp(snapped, range.first, range.second);
}

}  // namespace nome::viewer
