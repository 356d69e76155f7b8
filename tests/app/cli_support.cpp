#include "app/cli_support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/commands.hpp"

namespace nome::test {

std::string scratch_dir(const std::string& name) {
  // One folder per process: several checkouts may run the same tests at once on one machine.
  const auto dir =
      std::filesystem::temp_directory_path() / ("nome_app_tests_" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string private_scratch_dir(const std::string& name) {
  return scratch_dir(name + "_" + std::to_string(::getpid()));
}

CommandResult run_nome_in_process(const std::vector<std::string>& arguments) {
  std::vector<std::string> words{"nome"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  std::ostringstream out, err;
  std::streambuf* const cout_buffer = std::cout.rdbuf(out.rdbuf());
  std::streambuf* const cerr_buffer = std::cerr.rdbuf(err.rdbuf());
  CommandResult r;
  r.status = nome::cli::run(int(argv.size()), argv.data());
  std::cout.rdbuf(cout_buffer);
  std::cerr.rdbuf(cerr_buffer);
  r.out = out.str();
  r.err = err.str();
  return r;
}

CommandResult run_nome_in_process(const std::string& arguments) {
  std::istringstream words(arguments);
  std::vector<std::string> split;
  for (std::string word; words >> word;) split.push_back(word);
  return run_nome_in_process(split);
}

CommandResult run_nome(const std::string& arguments) {
  return run_nome_prefixed("", arguments);
}

CommandResult run_command(const std::string& command) {
  static int counter = 0;
  const std::string base = scratch_dir("run_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const std::string out = base + "/out", err = base + "/err";
  const int raw = std::system((command + " >" + out + " 2>" + err + " </dev/null").c_str());
  CommandResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  std::ostringstream o, e;
  o << std::ifstream(out).rdbuf();
  e << std::ifstream(err).rdbuf();
  r.out = o.str();
  r.err = e.str();
  std::filesystem::remove_all(base);
  return r;
}

CommandResult run_nome_prefixed(const std::string& prefix, const std::string& arguments) {
  return run_command(prefix + " " + std::string(NOME_EXECUTABLE) + " " + arguments);
}

}  // namespace nome::test
