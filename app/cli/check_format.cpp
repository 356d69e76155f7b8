#include "cli/check_format.hpp"

#include <sstream>

namespace nome::cli {
namespace {

std::size_t count_places_of(const PrintCheck& check, FindingKind kind) {
  std::size_t n = 0;
  for (const PrintPlace& p : check.places) n += p.kind == kind;
  return n;
}

void write_print_place(std::ostream& out, const PrintPlace& p) {
  out << "  " << to_string(p.kind);
  if (p.kind == FindingKind::near_miss) out << " " << p.distance << " thin";
  out << " at (" << p.position.x << ", " << p.position.y << ", " << p.position.z << "), face " << p.face;
  if (p.other_face != no_index) out << " and face " << p.other_face;
  out << " (" << p.size
      << (p.kind == FindingKind::near_miss  ? " vertices"
          : p.kind == FindingKind::crossing ? " triangle pairs"
                                            : " faces")
      << ")\n";
}

}  // namespace

std::string check_summary(const PrintCheck& c) {
  std::ostringstream out;
  out << (c.is_printable() ? "printable" : "NOT printable") << ": " << c.fold_over_faces.size()
      << " fold-over faces, " << c.near_misses.size() << " vertices closer than the wall " << c.min_wall
      << ", " << c.crossings.curves << " crossing curves";
  return out.str();
}

std::string check_text(const PrintCheck& c) {
  std::ostringstream out;
  out << "printable:    " << (c.is_printable() ? "yes" : "no") << "\n";
  out << "offset:       " << c.offset_distance << " (minimum wall " << c.min_wall << ")\n";
  out << "fold-overs:   " << c.fold_over_faces.size() << " faces in "
      << count_places_of(c, FindingKind::fold_over) << " places (the offset turns inside out there)\n";
  out << "near misses:  " << c.near_misses.size() << " vertices in "
      << count_places_of(c, FindingKind::near_miss) << " places (two sheets closer than the wall)\n";
  out << "crossings:    " << c.crossings.pairs.size() << " triangle pairs on " << c.crossings.curves
      << " curves (the slab fuses there: by design in one-sided surfaces)\n";
  if (!c.places.empty()) out << "worst places (faces of the surface before the offset):\n";
  for (std::size_t i = 0; i < c.places.size() && i < listed_places; ++i) write_print_place(out, c.places[i]);
  if (c.places.size() > listed_places) out << "  ... and " << c.places.size() - listed_places << " more\n";
  return out.str();
}

std::string check_json(const PrintCheck& c) {
  std::ostringstream out;
  out.precision(17);
  out << "{\"printable\": " << (c.is_printable() ? "true" : "false") << ", \"offset\": " << c.offset_distance
      << ", \"min_wall\": " << c.min_wall << ", \"fold_overs\": " << c.fold_over_faces.size()
      << ", \"crossing_pairs\": " << c.crossings.pairs.size()
      << ", \"crossing_curves\": " << c.crossings.curves << ", \"near_misses\": " << c.near_misses.size()
      << ", \"places\": [";
  for (std::size_t i = 0; i < c.places.size(); ++i) {
    const PrintPlace& p = c.places[i];
    out << (i ? ", " : "") << "{\"kind\": \"" << to_string(p.kind) << "\", \"position\": [" << p.position.x
        << ", " << p.position.y << ", " << p.position.z << "], \"face\": " << p.face << ", \"other_face\": ";
    if (p.other_face == no_index)
      out << "null";
    else
      out << p.other_face;
    out << ", \"distance\": " << p.distance << ", \"size\": " << p.size << "}";
  }
  out << "]}\n";
  return out.str();
}

}  // namespace nome::cli
