#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <sstream>

#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "nome/error.hpp"

namespace nome::cli {
namespace {

struct Command {
  const char* name;
  int (*run)(const std::vector<std::string>&);
  const char* summary;
};

const Command commands[] = {
    {"info", info_command, "print the topology report of a file (V, E, F, chi, orientable, borders, genus)"},
    {"export", export_command, "write the result as .obj, .stl or .3mf"},
    {"check", check_command, "is the solid printable? fold-overs, near misses, crossings (exit 3: no)"},
    {"render", render_command, "draw the result headless into a PNG (EGL or OSMesa, no display needed)"},
    {"version", version_command, "print the version and git commit (--verbose: GL backend, shader folder)"},
};

void print_help(std::ostream& out) {
  out << "Nome: a modeller for 2-manifold surfaces, single-sided ones included.\n\n"
         "usage: nome [FILE] [--script S.txt]   the viewer window (nome x.obj --help: its options)\n"
         "       nome COMMAND [options]         (nome COMMAND --help explains every option)\n\ncommands:\n";
  for (const Command& c : commands)
    out << "  " << c.name << std::string(10 - std::string(c.name).size(), ' ') << c.summary << "\n";
}

// `nome FILE ...` and `nome --script ...` open the viewer: a first word that is no command but names a
// file (or an option of the viewer) belongs to it.
bool is_viewer_call(const std::vector<std::string>& args) {
  const std::string& first = args[0];
  for (const Command& c : commands)
    if (first == c.name) return false;
  if (first == "--script" || first == "--size") return true;
  return first.find('.') != std::string::npos || first.find('/') != std::string::npos;
}

int run_guarded(const std::string& name, int (*command)(const std::vector<std::string>&),
                const std::vector<std::string>& args) {
  try {
    return command(args);
  } catch (const UsageError& e) {
    const std::string program = name.empty() ? "nome" : "nome " + name;
    std::cerr << program << ": " << e.what() << "\n(see '" << program << " --help')\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "nome: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    // A scene error lists several located errors, one a line: each gets the prefix.
    std::istringstream lines(e.what());
    for (std::string line; std::getline(lines, line);) std::cerr << "nome: " << line << "\n";
    return 1;
  }
}

}  // namespace

int run(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() && std::getenv("DISPLAY")) return run_guarded("", view_command, args);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help(args.empty() ? std::cerr : std::cout);
    return args.empty() ? 2 : 0;
  }
  if (is_viewer_call(args)) return run_guarded("", view_command, args);
  const std::string name = args[0] == "--version" ? "version" : args[0];
  args.erase(args.begin());
  for (const Command& c : commands)
    if (name == c.name) return run_guarded(name, c.run, args);
  std::cerr << "nome: unknown command '" << name << "'\n";
  print_help(std::cerr);
  return 2;
}

}  // namespace nome::cli
