#pragma once
/// @file SheetInterpolation.h
/// @brief A medial sheet of a solid as triangles (thesis §6.3.9, DESIGN.md §3 "Sheets"):
/// every vertex the centre of a ball touching both generators of the sheet's pair.
///
/// The sheet is parameterised by the touchpoint q on one generator of its pair, P (a face
/// when the pair has one): for each q the ball touching P at q and the other generator O
/// is found by Newton on S_P(q) + r·N_P(q) = S_O(q_O) + r·N_O(q_O) (unknowns q_O and r),
/// from a neighbour, or — when that does not converge — by bracketing the root of the
/// monotone function r ↦ distance(S_P + r·N_P, O) − r and polishing. The sheet's domain in
/// q is bounded by the P-touchpoints of the balls on its border: the stretches of the given
/// seams whose balls touch both P and O (checked, not assumed: a seam's triplet changes
/// where a touchpoint moves onto a reflex edge), and its convex edges (radius 0). Pieces
/// are joined where they share a ball; an end with no partner is joined to the nearest
/// free end along a straight line in q (the side of P's domain, where the sheet of P and O
/// continues as the sheet of P's reflex edge and O), solved point by point. The domain is
/// triangulated with CGAL's constrained Delaunay triangulation (DomainTriangulation) and
/// refined by centroids until every triangle's centroid is within `tolerance` of the exact
/// sheet (position and radius) and no edge is longer than `maxEdge`.

#include "mat3d/Generator3D.h"
#include "mat3d/MAT3D.h"
#include "medial/SolidBoundary.h"
#include "sheets/SheetSide.h"

#include <array>
#include <string>
#include <vector>

namespace exactmat
{

/// A curve of medial balls on (part of) a sheet's border: a seam, in order.
struct SheetBorderCurve
{
  Vec3List centres;
  std::vector<double> radii;
  std::vector<int> ids; ///< the caller's numbering of the points (kept on the sheet's vertices)
  /// Where each ball touches (a rim's one osculating point); empty when not given.
  Vec3List touches;
};

struct SheetOptions
{
  double tolerance = 1e-4; ///< centroid deviation (position, radius), fraction of the size
  double maxEdge = 0.05;   ///< longest triangle edge, fraction of the size
  int maxVertices = 200000;
  /// The whole exact boundary (optional, recommended): the border's turning points and the
  /// points that close it along a side are checked to be medial (distance = radius), so a
  /// border closed the wrong way fails the sheet instead of filling outside the MAT.
  const SolidBoundary* exact = nullptr;
};

struct SheetVertex
{
  Vec3 x = Vec3::Zero();
  double r = 0.0;
  /// Touchpoint parameters and touchpoints on the pair's generators, in the order given.
  std::array<Vec2, 2> q{ { Vec2::Zero(), Vec2::Zero() } };
  std::array<Vec3, 2> touch{ { Vec3::Zero(), Vec3::Zero() } };
  /// Where the vertex lies in the sheet's parameter domain: its touch parameters on the
  /// side that carries it (a reflex edge's (t, θ) between two reflex edges one of which is
  /// curved), or its coordinates in the plane fitted to the border when both sides are
  /// (straight) reflex edges or corners.
  Vec2 domain = Vec2::Zero();
  int source = -1;       ///< the border curve point it is (SheetBorderCurve::ids), or −1
  bool border = false;   ///< on the sheet's border (from a curve, a convex edge or a gap)
  bool convexEdge = false; ///< radius 0 on a convex edge of the solid
};

struct MedialSheetMesh
{
  std::array<int, 2> generators{ { -1, -1 } };       ///< each side's first generator
  std::array<std::vector<int>, 2> members;          ///< each side's generators (sheetSide)
  std::vector<int> traced;                          ///< the MAT3D::sheets it joins (interpolateSheets)
  int parameterisedBy = 0;  ///< 0 or 1: which of the pair carries the parameter domain
  std::vector<SheetVertex> vertices;
  std::vector<std::array<int, 3>> triangles;
  int loops = 0;            ///< border loops (1 + holes, or several pieces)
  /// The border loops' vertex counts: the first loopSizes[0] vertices are the first loop in
  /// order (closed: the last joins the first), the next loopSizes[1] the second, …
  std::vector<int> loopSizes;
  int gapVertices = 0;      ///< border vertices solved along a side of P's domain
  double maxDeviation = 0.0; ///< largest centroid deviation of the final triangles, fraction of the size
  /// The exact balls at the domain centroids of the final triangles (where they solve):
  /// sheet points that are not vertices, to measure a fit between the vertices (SheetFit).
  std::vector<SheetVertex> checkPoints;
  /// A vertex whose ball touches a whole circle of side 1 (a cone sheet's apex, where a
  /// centre curve ends: CapSheet.h), or −1: the triangles at it cover the band between that
  /// circle and their other corners' touches on side 1, not the fan their corners make.
  int apex = -1;
  Vec3 apexCircleCentre = Vec3::Zero(), apexCircleAxis = Vec3::UnitZ();
  double apexCircleRadius = 0.0;
  /// Vertices whose balls are within this of the apex's (centre and radius) stand for it:
  /// their touches on side 1 swing round its circle with the direction from the apex,
  /// however close they come (a cap cut at a slant), so the band from the circle to the
  /// farther vertices measures what the triangles there cover; triangles with two or three
  /// such corners add nothing to it.
  double apexReach = 0.0;
  bool nearApex(int v) const
  {
    return apex >= 0 && (v == apex ||
      ((vertices[v].x - vertices[apex].x).norm() <= apexReach && std::abs(vertices[v].r - vertices[apex].r) <= apexReach));
  }
  double area() const;
};

/// Traced sheets (generator pairs) that are one sheet: the same two sides. Groups with no
/// traced pair follow: faces meeting at a convex edge that no seam lists as a pair.
struct SheetGroup
{
  std::vector<int> a, b;    ///< the sides (sheetSide), a < b
  std::vector<int> traced;  ///< indices into the given pairs (empty: from a convex edge)
};
std::vector<SheetGroup> groupSheets(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const std::vector<std::array<int, 2>>& pairs);

/// The convex edges between a face of one side and a face of the other: where the sheet
/// reaches the boundary with radius 0 (taken from the boundary, not from the traced sheets,
/// which list an edge only with a pair some seam has).
std::vector<int> convexEdgesBetween(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const SheetGroup& group);

/// The sheet between sides a and b (sheetSide) bounded by `curves` (seams; only their
/// stretches on this sheet are used) and the convex edges `convexEdges` (Boundary3D
/// indices). Throws InputError naming the sheet when its border does not close or its
/// domain cannot be triangulated.
MedialSheetMesh interpolateSheet(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const std::vector<int>& a, const std::vector<int>& b, const std::vector<SheetBorderCurve>& curves,
  const std::vector<int>& convexEdges, const SheetOptions& options = {});

/// The sheet of a group (its two sides), bounded by `curves` and by the convex edges
/// between its sides (convexEdgesBetween); the mesh's `traced` is the group's.
MedialSheetMesh interpolateSheet(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const SheetGroup& group, const std::vector<SheetBorderCurve>& curves, const SheetOptions& options = {});

/// Every sheet of a traced MAT: MAT3D::sheets grouped by their sides (sheetSide), each
/// group's border from its seams' balls (ids: the ball's index along its seam) and convex
/// edges. A sheet that cannot be interpolated is left empty (no triangles) and its reason
/// put in `failures` (its index in the result and the InputError's message).
std::vector<MedialSheetMesh> interpolateSheets(const Boundary3D& boundary, const MAT3D& mat,
  const SheetOptions& options, std::vector<std::pair<int, std::string>>& failures);

} // namespace exactmat
