#pragma once

#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "app/cli_support.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/query/screen_projection.hpp"

namespace nome::test {

// The viewer's window in the scripted sessions: Xvfb's screen holds it whole.
constexpr int viewer_width = 1280;
constexpr int viewer_height = 800;

// Runs `nome ARGUMENTS` on a fresh virtual display (xvfb-run), as a user's session would run.
CommandResult run_viewer(const std::string& arguments);

// The camera of the viewer after the script command `view AZ EL` (framed to the mesh).
ScreenProjection viewer_projection(const Mesh& mesh, double azimuth, double elevation);

// A window pixel where clicking in vertex mode picks vertex v (checked with the kernel's own pick),
// if v is visible there.
std::optional<glm::dvec2> click_position(const Mesh& mesh, const ScreenProjection& projection, Index v);

}  // namespace nome::test
