#ifndef vtkMATBoundaryConversion_h
#define vtkMATBoundaryConversion_h
/**
 * @file vtkMATBoundaryConversion.h
 * @brief Exact conversion between a vtkUnstructuredGrid of (rational) Bézier cells and the
 * kernel's B-rep input pieces (DESIGN.md §2). Not wrapped: used by the ExactMAT modules.
 *
 * Curves: `VTK_BEZIER_CURVE` (VTK order: both ends first, then interior control points),
 * `VTK_LINE`, `VTK_POLY_LINE` (each segment a degree-1 edge). Surfaces:
 * `VTK_BEZIER_QUADRILATERAL`, `VTK_BEZIER_TRIANGLE`, `VTK_QUAD`, `VTK_TRIANGLE`. Weights
 * come from the `RationalWeights` point array, degrees from `HigherOrderDegrees`, entity
 * ids from `EdgeId` / `FaceId`. Every failure throws exactmat::InputError naming the cell.
 */

#include "brep/Boundary2D.h"
#include "brep/Boundary3D.h"
#include "shapes/Catalogue.h"

#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <memory>
#include <string>
#include <vector>

namespace exactmat
{

/// The curve cells of `grid` as B-rep pieces (end point ids = VTK point ids). Throws
/// InputError for an empty grid, surface or unsupported cells, a degree that does not
/// match the point count, non-finite coordinates or weights ≤ 0 (naming the cell).
std::vector<CurvePiece> curvePiecesFromGrid(vtkUnstructuredGrid* grid);

/// The surface cells of `grid` as B-rep pieces (triangles keep their triangular net).
std::vector<PatchPiece> patchPiecesFromGrid(vtkUnstructuredGrid* grid);

/// Faces as the user knows them: each face's FaceId (the file's entity), or its cell's
/// index when the grid has none. Where one entity is tiled into several cells (a STEP face
/// cut into Bézier patches) the cell follows after a colon, "12:40", so every face has a
/// label of its own: the sheets' topology (SheetGovernors, SheetConvexEdges) names faces by
/// these labels, and two tiles under one name would merge their sheets' pairs.
class FaceLabels
{
public:
  explicit FaceLabels(const Boundary3D& boundary);
  /// The face's own label: "4", or "12:40" for one tile of entity 12.
  std::string face(int face) const;
  /// The entity alone ("12" for each of its tiles), for names of whole sheets.
  std::string entity(int face) const;
  /// A generator of a solid's MAT (a face, a reflex edge or a reflex corner) by the faces it
  /// lies on: "4", "12/13", "3/9/10".
  std::string generator(const std::vector<int>& faces) const;
  /// A convex (or any) edge by its two faces: "4/7".
  std::string edge(int edge) const;

private:
  const Boundary3D& B;
  std::vector<int> EntityFaces; ///< per face: how many faces share its entity
};

/// True when the grid holds surface cells (a 3D boundary), false for curve cells.
bool gridHasSurfaceCells(vtkUnstructuredGrid* grid);

/// Builds a grid of Bézier cells. Every cell gets `EdgeId`/`FaceId` = its entity and
/// `ParameterRange` = its knot span; all points get `RationalWeights`; end points of
/// curve cells that coincide exactly share one VTK point.
class BoundaryGridBuilder
{
public:
  BoundaryGridBuilder();
  void addCurve(const BezierCurve& curve, int entity, double t0 = 0.0, double t1 = 1.0);
  void addPatch(const BezierPatch& patch, int entity, double u0 = 0.0, double u1 = 1.0,
    double v0 = 0.0, double v1 = 1.0);
  void addTriangle(const TriangleNet& triangle, int entity);
  /// Every Bézier piece of every entity of `shape`.
  void addShape(const Shape& shape);
  vtkSmartPointer<vtkUnstructuredGrid> grid() const { return Grid; }

private:
  vtkIdType insertPoint(const Vec4& homogeneousPoint, bool shareable);
  void addCellData(int entity, const double* range, int rangeSize, int p, int q);

  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  struct State;
  std::shared_ptr<State> Impl;
};

} // namespace exactmat

#endif
