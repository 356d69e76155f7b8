#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "nome/mesh/mesh.hpp"
#include "render/snapshot.hpp"

namespace nome::cli {

// --turntable N, --sheet and --frame-ms, for `nome render`.
std::vector<OptionSpec> turntable_options();

// Checks the turntable options against the output's name (.gif needs --turntable; --sheet and --frame-ms
// need it too). Throws UsageError.
void check_turntable_arguments(const Arguments& parsed, const std::filesystem::path& out);

// Renders the turntable (a current context needed) and writes it: an animated GIF for OUT.gif, a contact
// sheet for OUT.png with --sheet, else the frames OUT_001.png ... Returns what was written, for the log.
std::string write_turntable(const Mesh& mesh, render::SnapshotOptions options, const Arguments& parsed,
                            const std::filesystem::path& out);

}  // namespace nome::cli
