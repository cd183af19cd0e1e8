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

/// Where a solid is placed: x ↦ scale · rotation · x + offset, its weights multiplied by
/// weightFactor.
struct Placement
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double scale = 1.0;
  Vec3 offset = Vec3::Zero();
  double weightFactor = 1.0;
};

/// A small solid far from the origin: turned by 0.7 rad about (0.3, −0.5, 0.8), scaled by
/// 1e-3, moved 1e5 × that scale along (1, −0.7, 0.4) (some 3e4 × a unit solid's size),
/// weights × 1e20 — the swept solids' invariance tests' placement.
Placement farFromTheOrigin();

/// Where a point of the placed solid was before (the inverse map; lengths: divide by scale).
inline Vec3 unplaced(const Placement& placed, const Vec3& x)
{
  return placed.rotation.transpose() * (x - placed.offset) / placed.scale;
}

inline std::vector<PatchPiece> movedPieces(std::vector<PatchPiece> pieces, const Placement& placed)
{
  return movedPieces(std::move(pieces), placed.rotation, placed.scale, placed.offset, placed.weightFactor);
}

} // namespace exactmat
