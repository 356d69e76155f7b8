#pragma once

#include <string>
#include <vector>

namespace nome::cli {

// Each command takes its arguments (after the command word) and returns the exit status:
// 0 success, 1 an error in the input (printed as `nome: FILE:LINE:COL: message`), 2 a usage error.
int info_command(const std::vector<std::string>& args);
int export_command(const std::vector<std::string>& args);
// `nome check`: exit 3 when the solid is not printable.
int check_command(const std::vector<std::string>& args);
int render_command(const std::vector<std::string>& args);
// `nome version [--verbose]` and `nome --version`: version, git commit, GL backend and shader folder.
int version_command(const std::vector<std::string>& args);
// `nome [FILE] [--script S.txt]`: the viewer window.
int view_command(const std::vector<std::string>& args);

// Dispatches `nome COMMAND ...`; catches every error so no input can crash the program.
int run(int argc, char** argv);

}  // namespace nome::cli
