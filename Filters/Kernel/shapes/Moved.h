#pragma once
/// @file Moved.h
/// @brief A solid's faces moved, rotated, scaled and reweighted: the same solid in another
/// frame, for the invariance tests and benchmarks (the MAT must come out the same,
/// transformed — DESIGN.md §3, Numerics).

#include "brep/Boundary3D.h"

#include <vector>

namespace exactmat
{

/// Every control point x ↦ scale · rotation · x + offset, every piece's weights multiplied
/// by weightFactor (the surfaces are unchanged by a common factor of their weights).
std::vector<PatchPiece> movedPieces(std::vector<PatchPiece> pieces, const Eigen::Matrix3d& rotation,
  double scale, const Vec3& offset, double weightFactor = 1.0);

} // namespace exactmat
