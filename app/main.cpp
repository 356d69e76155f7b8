#include "cli/commands.hpp"
#include "nome/freed_memory.hpp"

int main(int argc, char** argv) {
  nome::keep_freed_memory();
  return nome::cli::run(argc, argv);
}
