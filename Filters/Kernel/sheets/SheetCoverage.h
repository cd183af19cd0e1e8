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
/// as that flat triangle: cut into 4 × 4, its points are the face at the interpolated touch
/// parameters (the sheet's triangles in the side's parameter plane, which tile it exactly;
/// SheetSide), or, where a sheet does not carry valid parameters (a rim's sheet), the flat
/// points projected onto the side's faces (Newton from the corners' touches). On a planar
/// face bounded by arcs, a side whose corners lie on a convex edge follows that arc. Flat
/// triangles cut across a curved face — next to a rim, where the touches leave the
/// osculating point like a square root, they miss 5e-3 of an ellipsoid — and chords of a
/// curved edge miss its segments (1e-4 of a cylinder's cap). A sheet's triangles at its
/// apex (a vertex touching a whole circle) count the band between that circle and their
/// other corners. `footprints` (optional, per face) adds what other elements cover (the
/// circles of contact of centre curves: centreCurveFootprints). Face areas are integrated
/// (Gauss–Legendre, cells halved until two rules agree to 1e-12). One entry per face or
/// group.
/// A face's area to 1e-12 of itself (Gauss–Legendre, cells halved until two rules agree).
double patchArea(const BezierPatch& patch);

std::vector<FaceCoverage> sheetCoverage(const Boundary3D& boundary, const std::vector<MedialSheetMesh>& meshes,
  const std::vector<double>& footprints = {});

} // namespace exactmat
