#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Sphere and ellipsoid (JIPCAD): a globe around the z axis with equatorial radius `radius` and polar
// radius `radius_z`, cut to longitudes [0, longitude_max] and latitudes [latitude_min, latitude_max]
// (degrees). Vertices v{i}_{j} (longitude i, latitude j from the south), the poles `south` and `north`
// (one vertex each), faces f{i}_{j} pointing outwards. A whole turn of longitude shares its seam.
struct SphereParams {
  double radius = 1, radius_z = 1;
  double longitude_max = 360, latitude_min = -90, latitude_max = 90;
  int longitude_segs = 16, latitude_segs = 8;
};
Piece sphere(const SphereParams& p);

}  // namespace nome::scene
