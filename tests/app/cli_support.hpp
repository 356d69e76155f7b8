#pragma once

#include <string>
#include <vector>

namespace nome::test {

// The project's example scenes, with the trailing slash.
inline const std::string assets = std::string(NOME_SOURCE_DIR) + "/assets/";

struct CommandResult {
  int status = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs a shell command line and captures its output.
CommandResult run_command(const std::string& command);

// Runs the built `nome` binary with the given arguments (a shell word list) and captures its output.
CommandResult run_nome(const std::string& arguments);
// The same, with a command word list put before the executable (`xvfb-run -a`, `env X=1`).
CommandResult run_nome_prefixed(const std::string& prefix, const std::string& arguments);

// The same command run inside the test process (nome::cli::run with std::cout and std::cerr captured): no
// process start, for tests that run many files; a crash takes the test binary down with it.
CommandResult run_nome_in_process(const std::vector<std::string>& arguments);
// The same with the arguments as one string split at spaces (no quoting: paths without spaces).
CommandResult run_nome_in_process(const std::string& arguments);

// A fresh scratch folder for one test's files.
std::string scratch_dir(const std::string& name);
// The same, private to this process: several checkouts' test runs on one machine share /tmp.
std::string private_scratch_dir(const std::string& name);

}  // namespace nome::test
