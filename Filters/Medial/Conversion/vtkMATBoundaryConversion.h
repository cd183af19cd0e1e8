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

/// A face as the user knows it: its FaceId (the entity), or its cell's index when the grid
/// has none.
std::string faceLabel(const Boundary3D& boundary, int face);
/// A generator of a solid's MAT (a face, a reflex edge or a reflex corner) by the faces it
/// lies on: "4", "12/13", "3/9/10".
std::string generatorLabel(const Boundary3D& boundary, const std::vector<int>& faces);

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
