#include "cli/report_format.hpp"

#include <sstream>

namespace nome::cli {
namespace {

const char* yes_no(bool b) {
  return b ? "yes" : "no";
}
const char* json_bool(bool b) {
  return b ? "true" : "false";
}

}  // namespace

std::string report_json(const TopologyReport& r) {
  std::ostringstream out;
  out << "{\"vertices\": " << r.vertices << ", \"edges\": " << r.edges << ", \"faces\": " << r.faces
      << ", \"chi\": " << r.chi << ", \"orientable\": " << json_bool(r.orientable)
      << ", \"borders\": " << r.borders << ", \"components\": " << r.components.size()
      << ", \"mobius_edges\": " << r.mobius_edges
      << ", \"manifold\": true, \"isolated_vertices\": " << r.isolated_vertices << ", \"parts\": [";
  for (size_t i = 0; i < r.components.size(); ++i) {
    const ComponentTopology& p = r.components[i];
    out << (i ? ", " : "") << "{\"vertices\": " << p.vertices << ", \"edges\": " << p.edges
        << ", \"faces\": " << p.faces << ", \"chi\": " << p.chi
        << ", \"orientable\": " << json_bool(p.orientable) << ", \"borders\": " << p.borders
        << ", \"genus\": " << p.genus << ", \"mobius_edges\": " << p.mobius_edges << "}";
  }
  out << "]}\n";
  return out.str();
}

std::string report_text(const TopologyReport& r) {
  std::ostringstream out;
  out << "vertices " << r.vertices << ", edges " << r.edges << ", faces " << r.faces << ", chi " << r.chi
      << "\n";
  out << "components " << r.components.size() << ", orientable " << yes_no(r.orientable) << ", borders "
      << r.borders << ", Möbius edges " << r.mobius_edges << "\n";
  if (r.isolated_vertices) out << "isolated vertices (in no face) " << r.isolated_vertices << "\n";
  for (size_t i = 0; i < r.components.size(); ++i) {
    const ComponentTopology& p = r.components[i];
    out << "  part " << i << ": V " << p.vertices << ", E " << p.edges << ", F " << p.faces << ", chi "
        << p.chi << ", " << (p.orientable ? "orientable" : "non-orientable") << ", borders " << p.borders
        << ", " << (p.orientable ? "genus " : "cross-caps ") << p.genus << ", Möbius edges " << p.mobius_edges
        << "\n";
  }
  return out.str();
}

}  // namespace nome::cli
