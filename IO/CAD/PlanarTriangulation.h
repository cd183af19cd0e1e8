#ifndef PlanarTriangulation_h
#define PlanarTriangulation_h
/**
 * @file PlanarTriangulation.h
 * @brief Triangles filling a planar region bounded by polygon loops (holes allowed) that use
 * the loops' vertices only, so every loop segment stays a whole triangle side: CGAL's
 * constrained Delaunay triangulation with exact predicates, the region found by the parity
 * of the loops crossed from outside.
 */

#include "common/Types.h"

#include <array>
#include <vector>

namespace exactmat
{
/// Triangles (indices into the loops' points, numbered loop after loop) counter-clockwise
/// about `normal`. Throws InputError when loops cross or two vertices coincide.
std::vector<std::array<int, 3>> triangulatePlanarLoops(
  const std::vector<Vec3List>& loops, const Vec3& normal);
} // namespace exactmat

#endif
