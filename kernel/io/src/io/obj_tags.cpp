#include "nome/io/obj_tags.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "io/obj_tag_lines.hpp"
#include "io/surface_views.hpp"
#include "nome/error.hpp"

namespace nome {
namespace {

struct TagTokens {
  std::vector<std::string> words;
  std::vector<int> columns;  // 1-based
};

TagTokens split_tag_line(const std::string& text) {
  TagTokens t;
  size_t i = 0;
  for (;;) {
    i = text.find_first_not_of(" \t\r", i);
    if (i == std::string::npos || text[i] == '#') return t;
    const size_t end = std::min(text.find_first_of(" \t\r#", i), text.size());
    t.words.push_back(text.substr(i, end - i));
    t.columns.push_back(int(i) + 1);
    i = end;
  }
}

// Gives each fan of faces around v (faces joined through edges at v) but the first its own copy of v;
// sharp edges and corner weights at v follow to the copies whose faces hold them.
void split_vertex_into_fans(PolygonSoup& soup, Index v) {
  std::vector<Index> faces;  // the faces at v, and where v is in each
  std::vector<Index> at;
  for (Index f = 0; f < soup.num_faces(); ++f)
    for (Index c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c)
      if (soup.face_vertices[c] == v) {
        faces.push_back(f);
        at.push_back(c);
        break;
      }
  auto neighbours = [&](size_t i) {  // the vertices before and after v in face i
    const Index first = soup.face_offsets[faces[i]], n = soup.face_offsets[faces[i] + 1] - first;
    const Index k = at[i] - first;
    return std::pair{soup.face_vertices[first + (k + n - 1) % n], soup.face_vertices[first + (k + 1) % n]};
  };
  std::vector<size_t> fan(faces.size());
  for (size_t i = 0; i < fan.size(); ++i) fan[i] = i;
  auto root = [&](size_t i) {
    while (fan[i] != i) i = fan[i] = fan[fan[i]];
    return i;
  };
  for (size_t i = 0; i < faces.size(); ++i)
    for (size_t j = i + 1; j < faces.size(); ++j) {
      const auto [pi, ni] = neighbours(i);
      const auto [pj, nj] = neighbours(j);
      if (pi == pj || pi == nj || ni == pj || ni == nj) fan[root(j)] = root(i);
    }
  std::vector<std::pair<size_t, Index>> copy_of_fan;  // fan root -> its vertex
  std::vector<Index> copy(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    const size_t r = root(i);
    auto it =
        std::find_if(copy_of_fan.begin(), copy_of_fan.end(), [&](const auto& p) { return p.first == r; });
    if (it == copy_of_fan.end()) {
      const Vec3 here = soup.positions[v];  // add_vertex may move the buffer
      const Index made = copy_of_fan.empty() ? v : soup.add_vertex(here);
      if (made != v && !soup.vertex_names.empty()) soup.vertex_names.push_back(soup.vertex_names[v]);
      copy_of_fan.emplace_back(r, made);
      it = copy_of_fan.end() - 1;
    }
    copy[i] = it->second;
    soup.face_vertices[at[i]] = copy[i];
  }
  for (auto& [a, b] : soup.sharp_edges)
    for (Index* end : {&a, &b}) {
      if (*end != v) continue;
      const Index other = end == &a ? b : a;
      for (size_t i = 0; i < faces.size(); ++i)
        if (neighbours(i).first == other || neighbours(i).second == other) *end = copy[i];
    }
  const size_t corners = soup.sharp_vertices.size();
  for (size_t k = 0; k < corners; ++k)
    if (soup.sharp_vertices[k].first == v)
      for (size_t c = 1; c < copy_of_fan.size(); ++c)
        soup.sharp_vertices.emplace_back(copy_of_fan[c].second, soup.sharp_vertices[k].second);
}

[[noreturn]] void fail_tag(const std::string& file, int line, int column, const std::string& what) {
  throw IoError(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what);
}

}  // namespace

ObjTag parse_obj_tag(const std::string& file, int line, const std::string& text) {
  const TagTokens t = split_tag_line(text);
  ObjTag tag;
  tag.line = line;
  if (t.words.size() < 3) fail_tag(file, line, 1, "expected 't NAME ints/floats/strings ...'");
  tag.name = t.words[1];
  int counts[3] = {0, 0, 0};
  if (std::sscanf(t.words[2].c_str(), "%d/%d/%d", &counts[0], &counts[1], &counts[2]) != 3 || counts[0] < 0 ||
      counts[1] < 0 || counts[2] < 0)
    fail_tag(file, line, t.columns[2],
             "expected the counts of ints, floats and strings as I/F/S, found '" + t.words[2] + "'");
  const size_t expected = 3 + size_t(counts[0]) + size_t(counts[1]) + size_t(counts[2]);
  if (t.words.size() < expected)
    fail_tag(file, line, 1,
             "'t " + tag.name + "' announces " + std::to_string(expected - 3) + " values, found " +
                 std::to_string(t.words.size() - 3));
  size_t k = 3;
  for (int i = 0; i < counts[0]; ++i, ++k) {
    long long value = 0;
    const std::string& w = t.words[k];
    const auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
    if (ec != std::errc() || ptr != w.data() + w.size())
      fail_tag(file, line, t.columns[k], "expected a whole number, found '" + w + "'");
    tag.ints.push_back(value);
  }
  for (int i = 0; i < counts[1]; ++i, ++k) {
    char* end = nullptr;
    const float value = std::strtof(t.words[k].c_str(), &end);
    if (end != t.words[k].c_str() + t.words[k].size())
      fail_tag(file, line, t.columns[k], "expected a number, found '" + t.words[k] + "'");
    tag.floats.push_back(value);
  }
  for (int i = 0; i < counts[2]; ++i, ++k) tag.strings.push_back(t.words[k]);
  return tag;
}

void apply_obj_tags(const std::string& file, const std::vector<ObjTag>& tags, PolygonSoup& soup) {
  auto index = [&](const ObjTag& tag, long long i, Index count, const char* what) {
    if (i < 0 || i >= (long long)count)
      throw IoError(file + ":" + std::to_string(tag.line) + ": 't " + tag.name + "' names " + what + " " +
                    std::to_string(i) + ", the file has " + std::to_string(count) + " (counted from 0)");
    return Index(i);
  };
  auto weight = [&](const ObjTag& tag, size_t i) {
    if (tag.floats.empty())
      throw IoError(file + ":" + std::to_string(tag.line) + ": 't " + tag.name + "' needs a sharpness");
    return tag.floats.size() > i ? tag.floats[i] : tag.floats[0];
  };
  for (const ObjTag& tag : tags) {
    if (tag.name == "crease") {
      // Vertex pairs, each with its own weight or all with the first.
      if (!tag.ints.empty() && soup.sharp_edge_weights.size() != soup.sharp_edges.size())
        soup.sharp_edge_weights.resize(soup.sharp_edges.size(), infinite_sharpness);
      for (size_t j = 0; j + 1 < tag.ints.size(); j += 2) {
        soup.sharp_edges.emplace_back(index(tag, tag.ints[j], soup.num_vertices(), "vertex"),
                                      index(tag, tag.ints[j + 1], soup.num_vertices(), "vertex"));
        soup.sharp_edge_weights.push_back(weight(tag, j / 2));
      }
    } else if (tag.name == "corner") {
      for (size_t j = 0; j < tag.ints.size(); ++j)
        soup.sharp_vertices.emplace_back(index(tag, tag.ints[j], soup.num_vertices(), "vertex"),
                                         weight(tag, j));
    } else if (tag.name == "hole") {
      for (long long f : tag.ints) soup.hole_faces.push_back(index(tag, f, soup.num_faces(), "face"));
    }
  }
  for (const ObjTag& tag : tags)
    if (tag.name == "splitvertex")
      for (long long v : tag.ints) split_vertex_into_fans(soup, index(tag, v, soup.num_vertices(), "vertex"));
}

ObjSubdivisionTags read_obj_subdivision_tags(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot open");
  const std::string file = path.string();
  ObjSubdivisionTags out;
  std::set<std::string> noted;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    const size_t i = text.find_first_not_of(" \t");
    if (i == std::string::npos || text[i] != 't' ||
        (i + 1 < text.size() && text[i + 1] != ' ' && text[i + 1] != '\t'))
      continue;
    const ObjTag tag = parse_obj_tag(file, line, text);
    const std::string word = tag.strings.empty() ? "" : tag.strings[0];
    if (tag.name == "interpolateboundary" && !tag.ints.empty()) {
      const long long mode = tag.ints[0];
      out.boundary = mode == 0   ? BoundaryMode::none
                     : mode == 1 ? BoundaryMode::edge_and_corner
                                 : BoundaryMode::edge_only;
    } else if (tag.name == "creasemethod" && !word.empty()) {
      out.crease_method = word == "chaikin" ? CreaseMethod::chaikin : CreaseMethod::uniform;
    } else if (tag.name == "smoothtriangles" && !word.empty()) {
      out.smooth_triangles = word == "smooth";
    } else if (tag.name != "crease" && tag.name != "corner" && tag.name != "hole" &&
               tag.name != "splitvertex" && noted.insert(tag.name).second) {
      out.notes.push_back(file + ":" + std::to_string(line) + ": 't " + tag.name +
                          "' ignored (hierarchical edits and face-varying options are not applied, as "
                          "OpenSubdiv's refiner does not apply them)");
    }
  }
  return out;
}

void write_obj_tags(std::ostream& out, const Mesh& mesh, const ObjSubdivisionTags& tags) {
  if (tags.boundary)
    out << "t interpolateboundary 1/0/0 "
        << (*tags.boundary == BoundaryMode::none              ? 0
            : *tags.boundary == BoundaryMode::edge_and_corner ? 1
                                                              : 2)
        << "\n";
  if (tags.crease_method)
    out << "t creasemethod 0/0/1 " << (*tags.crease_method == CreaseMethod::chaikin ? "chaikin" : "normal")
        << "\n";
  if (tags.smooth_triangles)
    out << "t smoothtriangles 0/0/1 " << (*tags.smooth_triangles ? "smooth" : "catmark") << "\n";
  char buf[64];
  // The vertices as the writer numbers them (a split vertex once).
  const std::vector<Index> numbers = written_vertex_numbers(mesh);
  auto number = [&](Index v) { return numbers.empty() ? v : numbers[v]; };
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    const float w = mesh.edge_sharpness(e);
    if (w <= 0.0f) continue;
    std::snprintf(buf, sizeof buf, "%.9g", double(w));
    out << "t crease 2/1/0 " << number(mesh.edge(e).vertices[0]) << ' ' << number(mesh.edge(e).vertices[1])
        << ' ' << buf << '\n';
  }
  for (Index v = 0; v < Index(mesh.vertex_sharpness_weights().size()); ++v) {
    if (mesh.vertex_sharpness(v) <= 0.0f || (!numbers.empty() && mesh.vertex_origins()[v] != v)) continue;
    std::snprintf(buf, sizeof buf, "%.9g", double(mesh.vertex_sharpness(v)));
    out << "t corner 1/1/0 " << number(v) << ' ' << buf << '\n';
  }
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_hole(f)) out << "t hole 1/0/0 " << f << '\n';
  // A vertex written once for several fans, so that reading the file gives the same surface again.
  std::vector<bool> is_split(mesh.vertex_origins().size(), false);
  for (Index v = 0; v < is_split.size(); ++v)
    if (mesh.vertex_origins()[v] != v) is_split[mesh.vertex_origins()[v]] = true;
  for (Index v = 0; v < is_split.size(); ++v)
    if (is_split[v]) out << "t splitvertex 1/0/0 " << number(v) << '\n';
}

}  // namespace nome
