#pragma once

#include <optional>
#include <string_view>

#include <glm/vec4.hpp>

#include "nome/mesh/mesh.hpp"

namespace nome::render {

// The axis a section plane is perpendicular to; the part on the axis' positive side is cut away.
enum class SectionAxis { x, y, z };

// "x", "y", "z"; none for anything else.
std::optional<SectionAxis> parse_section_axis(std::string_view name);

// The plane of DisplaySettings::section_plane that cuts away where the axis' coordinate exceeds `at`.
glm::vec4 section_plane(SectionAxis axis, double at);

// The middle of the mesh's bounding box along the axis (0 for an empty mesh).
double section_centre(const Mesh& mesh, SectionAxis axis);

}  // namespace nome::render
