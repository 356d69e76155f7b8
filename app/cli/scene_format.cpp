#include "cli/scene_format.hpp"

#include <sstream>

namespace nome::cli {
namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// `jipcad (decided by 'list' in a bank at f.nom:3:3)`.
std::string dialect_text(const scene::DialectChoice& d) {
  const std::string name = d.dialect == scene::Dialect::jipcad ? "jipcad" : "2016";
  return name + (d.cue.empty() ? " (the default: no statement decided)" : " (decided by " + d.cue + ")");
}

}  // namespace

std::string scene_text(const SceneDocument& document) {
  using scene::format_number;
  const scene::Scene& scene = *document.scene();
  std::ostringstream out;
  out << "scene " << scene.file() << "\n";
  out << "  dialect " << dialect_text(scene.dialect()) << "\n";
  for (const scene::Bank& bank : scene.banks()) {
    out << "  bank " << bank.name << "\n";
    for (scene::ParameterId id : bank.parameters) {
      const scene::Parameter& p = scene.parameters()[id];
      out << "    $" << p.full_name << " = " << format_number(p.value) << "  [" << format_number(p.min)
          << ", " << format_number(p.max) << "] step " << format_number(p.step)
          << (p.label.empty() ? "" : "  \"" + p.label + "\"") << "\n";
    }
  }
  for (const scene::SceneInstance& i : scene.instances()) {
    const PolygonSoup& s = i.geometry.soup;
    out << "  instance " << i.name << ": " << s.num_vertices() << " vertices, " << s.num_faces() << " faces";
    if (!i.geometry.rims.empty()) out << ", " << i.geometry.rims.size() << " rim lines";
    out << "\n";
  }
  const Document& edits = document.edits();
  if (!edits.consolidated_faces().empty()) {
    const PolygonSoup consolidated = edits.consolidated_soup();
    out << "  consolidated mesh: " << consolidated.num_vertices() << " vertices, " << consolidated.num_faces()
        << " faces\n";
  }
  if (!edits.deleted_faces().empty()) out << "  deleted faces: " << edits.deleted_faces().size() << "\n";
  if (!edits.sharp_edges().empty()) out << "  sharp edges: " << edits.sharp_edges().size() << "\n";
  return out.str();
}

std::string scene_json(const SceneDocument& document) {
  const scene::Scene& scene = *document.scene();
  std::ostringstream out;
  out << "{\"file\": " << quoted(scene.file()) << ", \"dialect\": " << quoted(dialect_text(scene.dialect()))
      << ", \"banks\": [";
  for (size_t b = 0; b < scene.banks().size(); ++b) {
    const scene::Bank& bank = scene.banks()[b];
    out << (b ? ", " : "") << "{\"name\": " << quoted(bank.name) << ", \"parameters\": [";
    for (size_t k = 0; k < bank.parameters.size(); ++k) {
      const scene::Parameter& p = scene.parameters()[bank.parameters[k]];
      out << (k ? ", " : "") << "{\"name\": " << quoted(p.full_name)
          << ", \"value\": " << scene::format_number(p.value) << ", \"min\": " << scene::format_number(p.min)
          << ", \"max\": " << scene::format_number(p.max) << ", \"step\": " << scene::format_number(p.step)
          << "}";
    }
    out << "]}";
  }
  out << "], \"instances\": [";
  for (size_t i = 0; i < scene.instances().size(); ++i) {
    const scene::SceneInstance& inst = scene.instances()[i];
    out << (i ? ", " : "") << "{\"name\": " << quoted(inst.name)
        << ", \"vertices\": " << inst.geometry.soup.num_vertices()
        << ", \"faces\": " << inst.geometry.soup.num_faces() << ", \"rims\": " << inst.geometry.rims.size()
        << "}";
  }
  const Document& edits = document.edits();
  const PolygonSoup consolidated = edits.consolidated_soup();
  out << "], \"edits\": {\"consolidated_vertices\": " << consolidated.num_vertices()
      << ", \"consolidated_faces\": " << consolidated.num_faces()
      << ", \"deleted_faces\": " << edits.deleted_faces().size()
      << ", \"sharp_edges\": " << edits.sharp_edges().size() << "}}";
  return out.str();
}

}  // namespace nome::cli
