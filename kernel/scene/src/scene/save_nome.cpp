#include "nome/scene/save_nome.hpp"

#include "nome/atomic_file.hpp"
#include "nome/scene/parser.hpp"
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"

namespace nome::scene {

std::string SceneWriter::run() {
  out_ << "# Saved by Nome: the sliders' current values, the scene, deletions and the consolidated mesh.\n";
  if (ast_.dialect.dialect == Dialect::jipcad) out_ << jipcad_header << "\n";
  const std::span<const StatementKind> kinds = statement_kinds();
  for (Index k = 0; k < kinds.size(); ++k)
    if (kinds[k].save) kinds[k].save(*this, k);
  return out_.str();
}

std::string SceneWriter::values(const Value* v, int count) const {
  std::string s;
  for (int i = 0; i < count; ++i) s += (i ? " " : "") + to_source(ast_.expressions, v[i]);
  return s;
}

std::string SceneWriter::names(const std::vector<Name>& list) {
  std::string s;
  for (size_t i = 0; i < list.size(); ++i) s += (i ? " " : "") + list[i].text;
  return s;
}

void SceneWriter::face(const FaceDecl& f, const char* indent) {
  out_ << indent << "face " << f.name.text << " (" << names(f.vertices) << ")"
       << (f.surface ? " surface " + f.surface->text : "") << " endface\n";
}

void SceneWriter::instance(const InstanceDecl& i, const char* indent) {
  out_ << indent << "instance " << i.name.text << " " << i.target.text;
  for (const TransformDecl& t : i.transforms) {
    switch (t.kind) {
      case TransformKind::translate:
        out_ << " translate (" << values(t.args, 3) << ")";
        break;
      case TransformKind::scale:
        out_ << " scale (" << values(t.args, 3) << ")";
        break;
      case TransformKind::rotate:
        out_ << " rotate (" << values(t.args, 3) << ") (" << values(t.args + 3, 1) << ")";
        break;
      case TransformKind::mirror:
        out_ << " mirror (" << values(t.args, 4) << ")";
        break;
    }
  }
  if (i.surface) out_ << " surface " << i.surface->text;
  if (i.backface) out_ << " backface " << i.backface->text;
  out_ << " endinstance\n";
}

std::string to_nome_text(const Scene& scene, const SceneEdits& edits) {
  return SceneWriter(scene, edits).run();
}

std::string to_nome_text(const Scene& scene) {
  return to_nome_text(scene, scene.edits());
}

void write_nome(const Scene& scene, const SceneEdits& edits, const std::filesystem::path& path) {
  const std::string text = to_nome_text(scene, edits);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

void write_nome(const Scene& scene, const std::filesystem::path& path) {
  write_nome(scene, scene.edits(), path);
}

}  // namespace nome::scene
