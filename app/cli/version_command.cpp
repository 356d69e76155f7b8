#include <exception>
#include <iostream>

#include "cli/arguments.hpp"
#include "cli/build_info.hpp"
#include "cli/commands.hpp"
#include "render/offscreen_context.hpp"
#include "render/shader_sources.hpp"

namespace nome::cli {

int version_command(const std::vector<std::string>& args) {
  Arguments parsed(
      "version", "nome version [--verbose]   (or nome --version [--verbose])",
      {{"--verbose", "-v", "", "also the GL backend found at run time and the shader folder in use"}});
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout << "Prints the version of Nome and the git commit it was built from.\n\n" << parsed.help();
    return 0;
  }
  if (!parsed.positionals().empty())
    throw UsageError("version takes no files, found '" + parsed.positionals()[0] + "'");
  std::cout << "nome " << project_version();
  if (!git_commit().empty()) std::cout << " (git " << git_commit() << ")";
  std::cout << "\n";
  if (!parsed.has("--verbose")) return 0;
  // A missing GL stack is what --verbose is asked to diagnose: it is reported, not an error.
  try {
    const render::OffscreenContext context;
    std::cout << "GL backend: " << context.platform() << ": " << context.description() << "\n";
  } catch (const std::exception& e) {
    std::cout << "GL backend: none (" << e.what() << ")\n";
  }
  std::cout << "shaders: " << render::shader_folder_in_use(render::shader_search_path()) << "\n";
  return 0;
}

}  // namespace nome::cli
