#pragma once
/// @file FaceCurveSearch.h
/// @brief What the searches for curves of balls that touch one face (rims: Rim.h; centre
/// curves: CentreCurve.h) are given: the boundary, its generators, how faces continue
/// across smooth edges, the scale and the step controls.

#include "mat3d/Generator3D.h"

#include <functional>
#include <vector>

namespace exactmat
{

struct FaceCurveSearch
{
  const Boundary3D* boundary = nullptr;
  const std::vector<Generator3D>* generators = nullptr; ///< faces first (generator f = face f)
  /// The face across side `side` of face `face` when the edge there is smooth, else −1.
  std::function<int(int, int)> smoothNeighbour;
  double size = 1.0;       ///< the solid's diagonal
  double tolerance = 1e-4; ///< chord deviation of the centre polyline, fraction of the size
  double maxStep = 0.05;   ///< longest step of the centre, fraction of the size
  int maxSteps = 200000;   ///< per curve (a runaway is an error)
  /// Positions in error messages are mapped through this (to the user's frame) when set.
  std::function<Vec3(const Vec3&)> toUser;
};

} // namespace exactmat
