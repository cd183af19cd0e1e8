#pragma once
/// @file CentroidRefinement.h
/// @brief A sheet's triangulated parameter domain refined by centroids (DESIGN.md §3,
/// "Sheets"): a triangle stays when the exact ball at its domain centroid is within the
/// tolerance of the linear interpolation of its corners (centre and radius) and no edge —
/// of it or of its footprints, the triangles of its corners' touches — is longer than
/// maxEdge; otherwise its centroid becomes a vertex. Rounds until none is
/// added (at most 200). The sheets solved over a domain of their own (a rim's plane, a
/// cap) use it; their solvers differ, the refinement does not.

#include "geometry/DomainTriangulation.h"
#include "sheets/SheetInterpolation.h"

#include <functional>
#include <string>

namespace exactmat
{

/// The exact ball over domain point w (inside triangle `corners` of the mesh); throws
/// InputError naming the sheet and the place when there is none.
using CentroidBall = std::function<SheetVertex(const Vec2& w, const std::array<int, 3>& corners)>;

/// Refines `domain` (whose vertices are `mesh.vertices`, in order), adding each new
/// vertex to the mesh and calling `added` after it; sets the mesh's triangles, maxDeviation
/// and checkPoints. `size` scales the options' fractions; `what` names the sheet in errors.
void refineByCentroids(DomainTriangulation& domain, MedialSheetMesh& mesh, const SheetOptions& options, double size,
  const CentroidBall& ball, const std::function<void()>& added, const std::string& what);

} // namespace exactmat
