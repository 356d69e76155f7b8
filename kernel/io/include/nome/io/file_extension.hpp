#pragma once

#include <filesystem>
#include <string>

namespace nome {

// The file's extension in lower case, with its dot (".obj"), or empty: file types are told by it.
std::string lower_extension(const std::filesystem::path& path);

}  // namespace nome
