#include "nome/scene/save_nome.hpp"

#include <sstream>

#include "nome/io/atomic_file.hpp"

namespace nome::scene {
namespace {

class Writer {
 public:
  explicit Writer(const Scene& scene) : scene_(scene), ast_(scene.ast()) {}

  std::string run() {
    out_ << "# Saved by Nome: the sliders' current values, the scene, deletions and the consolidated mesh.\n";
    for (const SurfaceDecl& s : ast_.surfaces)
      out_ << "surface " << s.name.text << " color (" << values(s.rgb, 3) << ") endsurface\n";
    for (const Bank& bank : scene_.banks()) {
      out_ << "bank " << bank.name << "\n";
      for (Index id : bank.parameters) {
        const Parameter& p = scene_.parameters()[id];
        out_ << "    set " << p.name << " " << format_number(p.value) << " " << format_number(p.min) << " "
             << format_number(p.max) << " " << format_number(p.step) << "\n";
      }
      out_ << "endbank\n";
    }
    for (const PointDecl& p : ast_.points)
      out_ << "point " << p.name.text << " (" << values(p.xyz, 3) << ") endpoint\n";
    for (const GeneratorDecl& g : ast_.generators) generator(g);
    for (const FaceDecl& f : ast_.faces) face(f, "");
    for (const PolylineDecl& p : ast_.polylines)
      out_ << "polyline " << p.name.text << " (" << names(p.vertices) << ")" << (p.is_loop ? " isloop" : "")
           << " endpolyline\n";
    for (const ObjectDecl& o : ast_.objects)
      out_ << "object " << o.name.text << " (" << names(o.faces) << ") endobject\n";
    for (const MeshDecl& m : ast_.meshes) {
      out_ << "mesh " << m.name.text << "\n";
      for (const FaceDecl& f : m.faces) face(f, "    ");
      for (const SharpDecl& s : m.sharps) out_ << "    sharp (" << names(s.vertices) << ") endsharp\n";
      out_ << "endmesh\n";
    }
    for (const GroupDecl& g : ast_.groups) {
      out_ << "group " << g.name.text << "\n";
      for (const InstanceDecl& i : g.instances) instance(i, "    ");
      out_ << "endgroup\n";
    }
    for (const InstanceDecl& i : ast_.instances) instance(i, "");
    if (!scene_.deleted_faces().empty()) {
      out_ << "delete\n";
      for (const std::string& f : scene_.deleted_faces()) out_ << "    face " << f << " endface\n";
      out_ << "enddelete\n";
    }
    if (!ast_.consolidated_faces.empty()) {
      out_ << "consolidate\n";
      for (const NamedFace& f : ast_.consolidated_faces) {
        out_ << "    consolidateface\n";
        for (const Name& v : f.vertices) out_ << "        vertex " << v.text << " endvertex\n";
        out_ << "    endconsolidateface\n";
      }
      out_ << "endconsolidate\n";
    }
    return out_.str();
  }

 private:
  std::string values(const Value* v, int count) const {
    std::string s;
    for (int i = 0; i < count; ++i) s += (i ? " " : "") + to_source(ast_.expressions, v[i]);
    return s;
  }
  static std::string names(const std::vector<Name>& list) {
    std::string s;
    for (size_t i = 0; i < list.size(); ++i) s += (i ? " " : "") + list[i].text;
    return s;
  }
  void generator(const GeneratorDecl& g) {
    static constexpr const char* keywords[][2] = {{"funnel", "endfunnel"},
                                                  {"tunnel", "endtunnel"},
                                                  {"circle", "endcircle"},
                                                  {"mobiusstrip", "endmobiusstrip"}};
    const auto& k = keywords[int(g.kind)];
    out_ << k[0] << " " << g.name.text << " (" << values(g.args.data(), int(g.args.size())) << ") " << k[1]
         << "\n";
  }
  void face(const FaceDecl& f, const char* indent) {
    out_ << indent << "face " << f.name.text << " (" << names(f.vertices) << ")"
         << (f.surface ? " surface " + f.surface->text : "") << " endface\n";
  }
  void instance(const InstanceDecl& i, const char* indent) {
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
    out_ << " endinstance\n";
  }

  const Scene& scene_;
  const SceneAst& ast_;
  std::ostringstream out_;
};

}  // namespace

std::string to_nome_text(const Scene& scene) {
  return Writer(scene).run();
}

void write_nome(const Scene& scene, const std::filesystem::path& path) {
  const std::string text = to_nome_text(scene);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace nome::scene
