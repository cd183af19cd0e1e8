#include "SolidBoundary.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

bool SolidBoundary::sameContact(
  const Vec3& x, double radius, const Vec3& a, const Vec3& b, double merge) const
{
  const double gap = (a - b).norm();
  if (gap <= merge)
    return true;
  if (gap > 0.2 * radius)
    return false;
  // (radius here: the ball's radius plus rounding.)
  return (nearestPoint(0.5 * (a + b)) - x).norm() <= radius;
}

std::vector<SolidBoundary::Contact> SolidBoundary::distinctContacts(
  std::vector<Minimum> minima, const Vec3& x) const
{
  std::sort(minima.begin(), minima.end(),
    [](const Minimum& a, const Minimum& b) { return a.distance < b.distance; });
  std::vector<Contact> out;
  if (minima.empty())
    return out;
  // Distinctness is relative to the ball, not the solid: a ball of radius 1e-12 in a
  // sheet 1e-12 thin (or of radius 1 in a bar 1e12 long) touches points that are
  // distinct at its own scale.
  const double scale = std::min(size(), std::max(minima.front().distance, 1e-300));
  const double merge = 1e-7 * scale;
  for (const Minimum& m : minima)
  {
    bool keep = true;
    for (const Minimum& other : minima)
    {
      // A border minimum with a nearer minimum next to it (on the neighbouring face) is
      // only the border of that face, not a touchpoint of the solid.
      if (m.oneSided && other.distance < m.distance - 1e-13 * scale &&
        (other.point - m.point).norm() < 0.05 * std::max(m.distance, merge))
      {
        keep = false;
      }
    }
    // The valley test uses the ball's own radius (the nearest minimum), not the counting
    // tolerance: near an osculating point two true touchpoints are only a hair apart.
    // Plus the rounding of the distances themselves, differences of coordinates of x's
    // magnitude: a ball 4e-7 across near the origin's unit has two feet either side of a
    // smooth junction 4e-12 apart, the valley between them "outside" by 1e-16.
    // And the input's own rounding: coplanar pieces of a cap far from the origin are each
    // tilted by it, and a touch near the edge between two has a foot on each, 1e-7 of the
    // size apart, the boundary between them "outside" by 1e-13 (an extruded L moved 4e4 ×
    // its size and turned: a seam point counted 4 touchpoints for 3).
    const double valley =
      minima.front().distance + 1e-12 * scale + 1e-15 * x.norm() + 64.0 * inputRounding() * size();
    for (const Contact& q : out)
      keep = keep && !sameContact(x, valley, q.point, m.point, merge);
    if (keep)
      out.push_back({ m.point, m.distance, m.source, m.parameters });
  }
  return out;
}

} // namespace exactmat
