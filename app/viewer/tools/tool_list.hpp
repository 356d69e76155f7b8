#pragma once

#include <memory>
#include <vector>

#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// The viewer's tools, in the order the window asks them (a click goes to the first that takes it;
// sections appear in this order).
std::vector<std::unique_ptr<Tool>> make_tools();

}  // namespace nome::viewer
