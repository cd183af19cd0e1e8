#include "PlanarTriangulation.h"

#include "geometry/DomainTriangulation.h"

namespace exactmat
{

std::vector<std::array<int, 3>> triangulatePlanarLoops(const std::vector<Vec3List>& loops, const Vec3& normal)
{
  // A frame of the plane with e1 × e2 = normal: counter-clockwise there is about the normal.
  const Vec3 n = normal.normalized();
  const Vec3 e1 = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  const Vec3 e2 = n.cross(e1);
  std::vector<std::vector<Vec2>> plane;
  for (const Vec3List& loop : loops)
  {
    plane.emplace_back();
    for (const Vec3& p : loop)
      plane.back().push_back(Vec2(p.dot(e1), p.dot(e2)));
  }
  return DomainTriangulation(plane).triangles();
}

} // namespace exactmat
