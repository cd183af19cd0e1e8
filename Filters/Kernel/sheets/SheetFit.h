#pragma once
/// @file SheetFit.h
/// @brief A medial sheet as a B-spline surface fitted to its exact balls: the thesis'
/// "approximate rational description (to within a defined tolerance) of the MAT" (§6.1,
/// §6.3.9), for the sheets the tracer gives as points.
///
/// The centre and the radius are fitted together, as one map (s, t) ↦ (x, y, z, r) over the
/// sheet's parameter domain (SheetVertex::domain: the touchpoint on the side that carries
/// the domain) scaled to [0,1]². Tensor-product B-splines of degree 3, clamped knots: least
/// squares on the sheet's vertices (each the exact centre and radius of a medial ball) plus
/// a small second-difference penalty on the control net. The penalty fixes the control
/// points the data hardly reaches (spans cut by the domain's border) and vanishes on linear
/// data, so a planar sheet with a linear radius is fitted exactly. The error is measured at
/// the vertices and at the exact balls at the triangles' centroids
/// (MedialSheetMesh::checkPoints), which the fit never sees: how the surface does between
/// the vertices. Every knot-span cell holding a point off by more than the tolerance, and
/// enough vertices (4(p + 1)) to fix the control points a split adds, is halved in both
/// directions and the fit repeated, up to `maxSpans` spans per direction; the round with
/// the smallest error is kept (spans the vertices cannot fix would only fit the vertices
/// better and the surface between them worse). So the fit is as good as the sheet's
/// vertices allow: a fit tolerance far below the sheet's own interpolation tolerance may
/// not be reached, and says so (withinTolerance).
///
/// The surface covers the domain's bounding box; the sheet is the part inside its border
/// loops (the triangles), returned as trimming loops in the surface's parameters. Only the
/// knot-span rectangles some triangle reaches are returned as Bézier patches; they may
/// reach past the border by less than one span.

#include "nurbs/BezierPatch.h"
#include "nurbs/KnotVector.h"
#include "sheets/SheetInterpolation.h"

#include <vector>

namespace exactmat
{

struct SheetFitOptions
{
  double tolerance = 1e-4; ///< largest |centre error| and |radius error|, fraction of the size
  int degree = 3;
  int maxSpans = 64;       ///< knot spans per direction at most
  double smoothing = 1e-12; ///< weight of the thin-plate energy against the data (per point)
};

/// One knot-span rectangle of the fit as Bézier patches: the centres (weights 1) and the
/// radius, whose Bézier coefficients are laid out as the patch's control points
/// (index i·(degree + 1) + j), so the same Bernstein basis interpolates both.
struct SheetFitPatch
{
  BezierPatch centre;
  std::vector<double> radius;
  double s0 = 0.0, s1 = 1.0, t0 = 0.0, t1 = 1.0; ///< the knot spans it covers
};

struct SheetFit
{
  int degree = 3;
  KnotVector knotsS, knotsT;
  int countS = 0, countT = 0;
  Vec3List centres;            ///< control net, index i·countT + j
  std::vector<double> radii;   ///< the radius's control values, same layout
  Vec2 domainOrigin = Vec2::Zero(), domainExtent = Vec2::Ones(); ///< s = (domain − origin) / extent
  std::vector<SheetFitPatch> patches; ///< the span rectangles the sheet's triangles reach
  /// The sheet's border loops (MedialSheetMesh::loopSizes) in (s, t): the trimming of the
  /// surface — the sheet is the part of [0,1]² inside the outer loop and outside the holes.
  std::vector<std::vector<Vec2>> trimLoops;

  int fittedPoints = 0;       ///< vertices the fit was computed from
  int checkedPoints = 0;      ///< check points it was measured at as well
  double vertexError = 0.0;   ///< largest error at the vertices, fraction of the size
  double checkError = 0.0;    ///< largest error at the check points (not fitted), fraction of the size
  double maxError() const { return std::max(vertexError, checkError); }
  bool withinTolerance = false;
  int rounds = 0;             ///< fits tried (the one with the smallest error is kept)

  Vec2 parameterOf(const Vec2& domain) const;
  /// Centre and radius at (s, t) ∈ [0,1]².
  void evaluate(const Vec2& st, Vec3& x, double& r) const;
};

/// Fits `mesh` (in the kernel's unit frame; `size` the solid's diagonal there). Throws
/// InputError when the sheet has no triangles or its domain has no extent.
SheetFit fitSheet(const MedialSheetMesh& mesh, double size, const SheetFitOptions& options = {});

} // namespace exactmat
