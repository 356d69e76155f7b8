#pragma once

#include <functional>
#include <string>

namespace nome::test {

// The text one frame of `draw` puts on screen, as ImGui's log captures it, drawn inside a window of a
// context of its own (no display, no renderer): what a user reads in a panel.
std::string imgui_text(const std::function<void()>& draw);

}  // namespace nome::test
