#pragma once
/// @file SheetCoverage.h
/// @brief Completeness of a solid's sheets, independent of how they were found: every point
/// of a face has one maximal ball, so the sheets' touchpoint footprints on a face add up to
/// its area.

#include "sheets/SheetInterpolation.h"

#include <cmath>
#include <vector>

namespace exactmat
{

/// One face, or one group of faces a sheet's side takes as one (coplanar faces, pieces of
/// one surface, every face a rim sheet touches).
struct FaceCoverage
{
  int face = -1;        ///< the face (the group's first)
  double area = 0.0;    ///< the face's (group's) area
  double covered = 0.0; ///< the footprints' total
  double shortfall() const { return area > 0.0 ? std::abs(covered - area) / area : 0.0; }
};

/// The footprints of `meshes` on every face. A sheet triangle's footprint on a side is the
/// triangle of its corners' touches there. On a curved face it is measured on the face, not
/// as the flat triangle of the three touches: when all three lie on one patch, the area of
/// the patch over the triangle of their parameters (a 7-point rule of degree 5 on
/// |S_u × S_v|) — footprints that share corners then tile the patch's parameter square
/// without gaps, however far the touches are apart (next to a rim they leave the
/// osculating point like a square root, where flat triangles cut across the face and
/// miss up to a few % of it). Footprints whose touches lie on different patches, or at a
/// point where the patch degenerates (a pole), are measured flat. A sheet's triangles at its
/// apex (a vertex touching a whole circle) count the band between that circle and their
/// other corners. `footprints` (optional, per face) adds what other elements cover (the
/// circles of contact of centre curves: centreCurveFootprints). Face areas are integrated
/// the same way (Gauss–Legendre on 16 × 16 cells). One entry per face or group.
std::vector<FaceCoverage> sheetCoverage(const Boundary3D& boundary, const std::vector<MedialSheetMesh>& meshes,
  const std::vector<double>& footprints = {});

} // namespace exactmat
