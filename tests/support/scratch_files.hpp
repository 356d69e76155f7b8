#pragma once

#include <filesystem>
#include <string>

namespace nome::test {

// A path for a test's file `name` in the folder `folder`_<pid> under the system's temporary folder (made if
// missing): each test process writes into its own folder.
std::filesystem::path scratch_path(const std::string& folder, const std::string& name);

// The file's bytes.
std::string file_bytes(const std::filesystem::path& path);

}  // namespace nome::test
