#pragma once

#include <string_view>

namespace nome::cli {

// project(VERSION) of the top CMakeLists.txt, e.g. "0.1.0".
std::string_view project_version();
// The commit the binary was built from ("1a2b3c4d5e6f", "-dirty" appended when tracked files differed);
// empty when it was not built from a git checkout.
std::string_view git_commit();

}  // namespace nome::cli
