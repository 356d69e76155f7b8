#include "nome/io/sif.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "nome/assert.hpp"
#include "nome/error.hpp"
#include "nome/scene/lexer.hpp"

namespace nome {
namespace {

using scene::Token;
using scene::TokenKind;

class SifParser {
 public:
  SifParser(std::string_view text, const std::string& file) : diagnostics_(file) {
    tokens_ = scene::tokenize(text, diagnostics_);
    throw_if_errors();
  }

  PolygonSoup run() {
    expect("(");
    if (!peek().is_word("SIF_SFF")) fail("'SIF_SFF'");
    take();
    while (peek().kind == TokenKind::number) take();  // format version
    while (peek().is_symbol("(")) {
      if (peek(1).is_word("solid")) {
        take();
        take();
        while (peek().is_symbol("(")) {
          if (!peek(1).is_word("shell")) fail("'(shell'");
          take();
          take();
          shell();
        }
        expect(")");
      } else {
        skip_list();  // units, bounding box and other annotations
      }
    }
    expect(")");
    if (peek().kind != TokenKind::end) fail("end of file");
    return std::move(soup_);
  }

 private:
  const Token& peek(size_t ahead = 0) const { return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)]; }
  const Token& take() {
    const Token& t = peek();
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return t;
  }
  [[noreturn]] void fail_at(const Token& t, const std::string& message) {
    diagnostics_.error(t.location, message);
    throw_if_errors();
    NOME_ASSERT(!"throw_if_errors throws once an error is recorded");
  }
  [[noreturn]] void fail(const std::string& expected) {
    fail_at(peek(), "expected " + expected + ", found " + peek().describe());
  }
  void throw_if_errors() {
    if (diagnostics_.has_errors()) throw IoError(diagnostics_.all().front().to_string());
  }
  void expect(const char* symbol) {
    if (!peek().is_symbol(symbol)) fail(std::string("'") + symbol + "'");
    take();
  }
  double number() {
    double sign = 1;
    if (peek().is_symbol("-")) {
      take();
      sign = -1;
    }
    if (peek().kind != TokenKind::number) fail("a number");
    return sign * take().number;
  }
  Index count() {
    const Token& t = peek();
    const double x = number();
    if (x < 0 || x != std::floor(x) || x > 1e8) fail_at(t, "expected a count, found " + t.describe());
    return Index(x);
  }
  void skip_list() {
    int depth = 0;
    do {
      if (peek().kind == TokenKind::end) fail("')'");
      if (peek().is_symbol("(")) ++depth;
      if (peek().is_symbol(")")) --depth;
      take();
    } while (depth > 0);
  }

  void shell() {
    const Index base = soup_.num_vertices();
    Index vertices = 0;
    while (peek().is_symbol("(")) {
      const Token& open = take();
      if (peek().is_word("vertices")) {
        take();
        const Index n = count();
        for (Index i = 0; i < n; ++i) {
          if (!peek().is_symbol("(") || !peek(1).is_word("v"))
            fail("'(v x y z)' (" + std::to_string(n) + " vertices announced at " + at(open) + ")");
          take();
          take();
          const double x = number(), y = number(), z = number();
          soup_.add_vertex({x, y, z});
          expect(")");
        }
        vertices += n;
        expect(")");
      } else if (peek().is_word("triangles")) {
        take();
        const Index n = count();
        for (Index i = 0; i < n; ++i) {
          if (!peek().is_symbol("(") || !peek(1).is_word("t"))
            fail("'(t a b c)' (" + std::to_string(n) + " triangles announced at " + at(open) + ")");
          take();
          take();
          std::array<Index, 3> corners{};
          for (Index& c : corners) {
            const Token& t = peek();
            c = count();
            if (c >= vertices)
              fail_at(t, "vertex index " + t.text + " out of range: the shell has " +
                             std::to_string(vertices) + " vertices");
            c += base;
          }
          soup_.add_face(corners);
          expect(")");
        }
        expect(")");
      } else {
        --pos_;
        skip_list();
      }
    }
    expect(")");
  }

  static std::string at(const Token& t) {
    return std::to_string(t.location.line) + ":" + std::to_string(t.location.column);
  }

  scene::Diagnostics diagnostics_;
  std::vector<Token> tokens_;
  size_t pos_ = 0;
  PolygonSoup soup_;
};

Vec3 triangle_normal(const PolygonSoup& s, Index f) {
  const Index* v = s.face_vertices.data() + s.face_offsets[f];
  return glm::cross(s.positions[v[1]] - s.positions[v[0]], s.positions[v[2]] - s.positions[v[0]]);
}

struct Pairing {
  double cost;
  Index first, second;
  std::array<Index, 4> quad;
};

// What joining triangles f and g into `quad` costs (how far they fold, and how far the quad's corners are
// from right angles), or nothing when they fold more than min_cos allows or the quad is not convex.
std::optional<double> pairing_cost(const PolygonSoup& soup, Index f, Index g,
                                   const std::array<Index, 4>& quad, double min_cos) {
  const Vec3 n1 = triangle_normal(soup, f), n2 = triangle_normal(soup, g);
  const double l1 = glm::length(n1), l2 = glm::length(n2);
  if (l1 == 0 || l2 == 0) return std::nullopt;
  const double fold = glm::dot(n1, n2) / (l1 * l2);
  if (fold < min_cos) return std::nullopt;
  const Vec3 normal = n1 + n2;
  double squareness = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3 p = soup.positions[quad[(i + 3) % 4]], q = soup.positions[quad[i]],
               r = soup.positions[quad[(i + 1) % 4]];
    if (glm::dot(glm::cross(q - p, r - q), normal) <= 0) return std::nullopt;
    const double lp = glm::length(p - q), lr = glm::length(r - q);
    if (lp > 0 && lr > 0) squareness = std::max(squareness, std::abs(glm::dot(p - q, r - q)) / (lp * lr));
  }
  return (1 - fold) + 0.5 * squareness;
}

}  // namespace

PolygonSoup pair_triangles(const PolygonSoup& soup, double max_fold_degrees) {
  const double min_cos = std::cos(max_fold_degrees * std::numbers::pi / 180);
  auto key = [](Index a, Index b) { return (std::uint64_t(a) << 32) | b; };
  // Directed edge a->b of a triangle -> (triangle, corner where the edge starts).
  std::unordered_map<std::uint64_t, std::pair<Index, Index>> directed;
  const Index nf = soup.num_faces();
  auto is_triangle = [&](Index f) { return soup.face_offsets[f + 1] - soup.face_offsets[f] == 3; };
  for (Index f = 0; f < nf; ++f)
    if (is_triangle(f))
      for (Index k = 0; k < 3; ++k) {
        const Index* v = soup.face_vertices.data() + soup.face_offsets[f];
        directed[key(v[k], v[(k + 1) % 3])] = {f, k};
      }
  std::vector<Pairing> candidates;
  for (Index f = 0; f < nf; ++f) {
    if (!is_triangle(f)) continue;
    const Index* v = soup.face_vertices.data() + soup.face_offsets[f];
    for (Index k = 0; k < 3; ++k) {
      const Index a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
      // Only consistently oriented neighbours: across a Möbius edge no quad keeps both orientations.
      const auto it = directed.find(key(b, a));
      if (it == directed.end() || it->second.first <= f) continue;
      const Index g = it->second.first;
      const Index* w = soup.face_vertices.data() + soup.face_offsets[g];
      const Index d = w[(it->second.second + 2) % 3];
      if (d == c) continue;
      const std::array<Index, 4> quad{a, d, b, c};
      if (const std::optional<double> cost = pairing_cost(soup, f, g, quad, min_cos))
        candidates.push_back({*cost, f, g, quad});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Pairing& x, const Pairing& y) {
    return x.cost != y.cost ? x.cost < y.cost : std::tie(x.first, x.second) < std::tie(y.first, y.second);
  });
  std::vector<Index> partner(nf, no_index);
  std::vector<const Pairing*> chosen(nf, nullptr);
  for (const Pairing& p : candidates) {
    if (partner[p.first] != no_index || partner[p.second] != no_index) continue;
    partner[p.first] = p.second;
    partner[p.second] = p.first;
    chosen[p.first] = &p;
  }
  PolygonSoup out;
  out.positions = soup.positions;
  out.vertex_names = soup.vertex_names;
  out.sharp_edges = soup.sharp_edges;
  const bool names = !soup.face_names.empty();
  std::vector<Index> parents;
  for (Index f = 0; f < nf; ++f) {
    if (chosen[f]) {
      out.add_face(chosen[f]->quad);
    } else if (partner[f] == no_index) {
      out.add_face(std::span<const Index>(soup.face_vertices.data() + soup.face_offsets[f],
                                          soup.face_offsets[f + 1] - soup.face_offsets[f]));
    } else {
      continue;  // the second triangle of a chosen pair
    }
    if (names) out.face_names.push_back(soup.face_names[f]);
    parents.push_back(f);
  }
  out.face_attributes = carried(soup.face_attributes, parents);
  return out;
}

PolygonSoup parse_sif(std::string_view text, const std::string& file, const SifOptions& options) {
  PolygonSoup soup = SifParser(text, file).run();
  return options.pair_triangles ? pair_triangles(soup, options.max_fold_degrees) : soup;
}

PolygonSoup read_sif(const std::filesystem::path& path, const SifOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_sif(text.str(), path.string(), options);
}

}  // namespace nome
