#include <exception>
#include <iostream>
#include <new>

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
    {"export", export_command, "write the result as .obj or .stl"},
    {"render", render_command, "draw the result headless into a PNG (EGL or OSMesa, no display needed)"},
};

void print_help(std::ostream& out) {
  out << "Nome: a modeller for 2-manifold surfaces, single-sided ones included.\n\n"
         "usage: nome COMMAND [options]      (nome COMMAND --help explains every option)\n\ncommands:\n";
  for (const Command& c : commands)
    out << "  " << c.name << std::string(10 - std::string(c.name).size(), ' ') << c.summary << "\n";
}

}  // namespace

int run(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help(args.empty() ? std::cerr : std::cout);
    return args.empty() ? 2 : 0;
  }
  const std::string name = args[0];
  args.erase(args.begin());
  for (const Command& c : commands) {
    if (name != c.name) continue;
    try {
      return c.run(args);
    } catch (const UsageError& e) {
      std::cerr << "nome " << name << ": " << e.what() << "\n(see 'nome " << name << " --help')\n";
      return 2;
    } catch (const std::bad_alloc&) {
      std::cerr << "nome: out of memory\n";
      return 1;
    } catch (const std::exception& e) {
      std::cerr << "nome: " << e.what() << "\n";
      return 1;
    }
  }
  std::cerr << "nome: unknown command '" << name << "'\n";
  print_help(std::cerr);
  return 2;
}

}  // namespace nome::cli
