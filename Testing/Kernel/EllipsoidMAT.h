#pragma once
/// @file EllipsoidMAT.h
/// @brief The ellipsoid's MAT in closed form, for the tests of its rim (TestMAT3D) and its
/// sheet (TestSheets): with semi-axes a, b and the shortest c, the sheet is the region of
/// the plane of the shortest axis inside the ellipse with semi-axes (a² − c²)/a and
/// (b² − c²)/b (the rim), with radius r = c·√(1 − x²/(a² − c²) − y²/(b² − c²)).

#include "common/Types.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

struct EllipsoidMedialOffsets
{
  double offPlane = 0.0;    ///< |coordinate along the shortest axis|
  double rimLevel = 0.0;    ///< Σ (x_k·a_k / (a_k² − c²))²: 1 on the rim, < 1 inside it
  double radiusError = 0.0; ///< |r − the closed-form radius at x|
};

/// How far the ball (x, r), in the ellipsoid's own frame, is from its closed-form MAT.
inline EllipsoidMedialOffsets ellipsoidMedialOffsets(const Vec3& semiAxes, const Vec3& x, double r)
{
  int shortest = 0;
  const double c = semiAxes.minCoeff(&shortest);
  double inside = 1.0;
  EllipsoidMedialOffsets out;
  for (int k = 0; k < 3; ++k)
    if (k != shortest)
    {
      const double squares = semiAxes(k) * semiAxes(k) - c * c;
      inside -= x(k) * x(k) / squares;
      out.rimLevel += std::pow(x(k) * semiAxes(k) / squares, 2);
    }
  out.offPlane = std::abs(x(shortest));
  out.radiusError = std::abs(r - c * std::sqrt(std::max(0.0, inside)));
  return out;
}

} // namespace exactmat
