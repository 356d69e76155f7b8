#include "cli/commands.hpp"

int main(int argc, char** argv) {
  return nome::cli::run(argc, argv);
}
