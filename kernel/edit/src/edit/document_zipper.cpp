#include <algorithm>

#include "nome/edit/document.hpp"
#include "nome/error.hpp"

// The document's zippers: along borders of a displayed mesh, and along chains of named vertices (rim
// lines, report 6.3).
namespace nome {

EditOutcome Document::zipper(const Mesh& displayed, const BorderSelection& a, const BorderSelection& b,
                             const ZipperOptions& options) {
  if (displayed.vertex_names().empty()) return {false, "the mesh has no vertex names to refer to"};
  ZipperFaces strip;
  try {
    strip = zipper_borders(displayed, a, b, options);
  } catch (const InvalidInputError& e) {
    return {false, e.what()};
  }
  std::vector<EditedFace> faces;
  for (const auto& polygon : strip.faces) {
    EditedFace face;
    for (Index v : polygon) face.vertices.push_back(displayed.vertex_names()[v]);
    faces.push_back(std::move(face));
  }
  // zipper_borders oriented the strip by the displayed mesh's faces.
  return add_strip(std::move(faces), strip, false);
}

EditOutcome Document::zip_chains(const std::vector<std::string>& chain_a,
                                 const std::vector<std::string>& chain_b, const ZipperOptions& options) {
  std::vector<Index> ids[2];
  const std::vector<std::string>* chains[2] = {&chain_a, &chain_b};
  for (int k = 0; k < 2; ++k)
    for (const std::string& name : *chains[k]) {
      const Index v = vertex_id(name);
      if (v == no_index) return {false, "no vertex named " + name};
      ids[k].push_back(v);
    }
  if (const Index v = chains_overlap(ids[0], ids[1]); v != no_index)
    return {false, "the two chains overlap at " + scene_.vertex_names[v]};
  // Chain B runs whichever way joins it to A with the cheaper strip: a rim line's direction is arbitrary.
  std::vector<Index> reversed(ids[1].rbegin(), ids[1].rend());
  ZipperFaces strip;
  try {
    const std::span positions(scene_.positions.data(), scene_.positions.size());
    strip = zipper_chains(positions, ids[0], ids[1], options);
    ZipperFaces other = zipper_chains(positions, ids[0], reversed, options);
    if (other.cost < strip.cost) strip = std::move(other);
  } catch (const InvalidInputError& e) {
    return {false, e.what()};
  }
  std::vector<EditedFace> faces;
  for (const auto& polygon : strip.faces) {
    EditedFace face;
    for (Index v : polygon) face.vertices.push_back(scene_.vertex_names[v]);
    faces.push_back(std::move(face));
  }
  return add_strip(std::move(faces), strip, true);
}

EditOutcome Document::add_strip(std::vector<EditedFace> faces, const ZipperFaces& strip, bool orient) {
  if (orient) {
    // The strip's faces agree with each other; the faces already along the chains decide which way all
    // of them run.
    int votes = 0;
    for (EditedFace& face : faces) {
      int face_votes = 0;
      if (std::string refused = check_face(face, {}, false, &face_votes); !refused.empty())
        return {false, refused};
      votes += face_votes;
    }
    if (votes < 0)
      for (EditedFace& face : faces) std::reverse(face.vertices.begin(), face.vertices.end());
  }
  std::vector<EditedFace> added;
  for (EditedFace& face : faces) {
    if (std::string refused = check_face(face, added, false); !refused.empty()) return {false, refused};
    face.name = next_face_name();
    added.push_back(std::move(face));
  }
  const std::string message = "zipper: " + std::to_string(strip.quads) + " quads and " +
                              std::to_string(strip.triangles) + " triangles added to the temporary mesh";
  execute(AddTemporary{std::move(added)});
  return {true, message};
}

}  // namespace nome
