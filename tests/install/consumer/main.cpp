// Subdivides the Möbius band given as argv[1] twice and prints its size and Euler characteristic.
#include <iostream>

#include "nome/io/obj.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/subdivide.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const nome::Mesh band = nome::subdivide(nome::build_mesh(nome::read_obj(argv[1])), {.levels = 2});
  const nome::TopologyReport report = nome::topology_report(band);
  std::cout << "faces " << band.num_faces() << " chi " << report.chi << " orientable " << report.orientable
            << "\n";
}
