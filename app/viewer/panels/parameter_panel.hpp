#pragma once

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "nome/scene/scene.hpp"
#include "viewer/layout.hpp"

namespace nome::viewer {

// What the parameter panel keeps over a session: the file's slider values (for "reset"), ranges the
// sculptor narrowed for this session, and the filter text.
struct ParameterPanelState {
  IdVector<scene::ParameterId, double> file_values;
  std::map<scene::ParameterId, std::pair<double, double>> ranges;
  std::array<char, 64> filter{};
  // What the slider menu's fields hold while it is open.
  double typed_value = 0.0;
  std::array<double, 2> typed_range{};

  // Takes the scene's present values as the file's (on open); again when the file's sliders changed.
  void track(const scene::Scene& scene);
  bool is_moved(const scene::Parameter& p, scene::ParameterId id) const;
  // The slider's range now: the file's, or the one narrowed for the session.
  std::pair<double, double> range(const scene::Parameter& p, scene::ParameterId id) const;
};

// A bank's sliders the filter lets through, in the bank's order (all for an empty filter). The filter
// matches part of a slider's name or its bank's name, ignoring case.
std::vector<scene::ParameterId> filtered_parameters(const scene::Scene& scene, const scene::Bank& bank,
                                                    const std::string& filter);

// The bank has one of the sliders.
bool holds_any(const scene::Bank& bank, const std::vector<scene::ParameterId>& parameters);

// The banks in the panel's order: those holding one of the `first` sliders (the ones the selection
// depends on), then the others, each group in the file's order.
std::vector<Index> bank_order(const scene::Scene& scene, const std::vector<scene::ParameterId>& first);

// The moves that return the bank's moved sliders to the file's values ("reset bank").
std::vector<std::pair<scene::ParameterId, double>> bank_reset(const scene::Scene& scene,
                                                              const scene::Bank& bank,
                                                              const ParameterPanelState& state);

// A slider value on its step from the minimum, within the range.
double snap_to_step(const scene::Parameter& p, double value, std::pair<double, double> range);

// The slider moves of one frame (a reset bank moves several), and whether they continue a drag that
// began in an earlier frame (the undo history merges such moves into one step).
struct ParameterMoves {
  std::vector<std::pair<scene::ParameterId, double>> moves;
  bool continues = false;
};

// The right sidebar's lower part: the filter box and every bank as a collapsing header in one
// scrolling panel. Sliders: drag, Ctrl+click to type, right-click for reset / type / range, arrow keys
// step the slider under the mouse; moved sliders are marked. Returns the slider moves of this frame;
// adds the bank headers that are wholly visible to `report`.
// `selected`: the sliders the selection depends on, whose banks come first (marked).
ParameterMoves draw_parameter_section(const scene::Scene& scene,
                                      const std::vector<scene::ParameterId>& selected,
                                      ParameterPanelState& state, LayoutReport& report);

}  // namespace nome::viewer
