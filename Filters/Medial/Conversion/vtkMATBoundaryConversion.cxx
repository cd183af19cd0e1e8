#include "vtkMATBoundaryConversion.h"

#include "common/InputError.h"
#include "nurbs/BezierExtraction.h"
#include "vtkExactMATArrayNames.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkHigherOrderQuadrilateral.h>
#include <vtkHigherOrderTriangle.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <array>
#include <cmath>
#include <map>

namespace exactmat
{

namespace
{
std::string cellName(vtkIdType cell, int entity, const char* kind)
{
  std::string s = "cell " + std::to_string(cell);
  if (entity >= 0 && entity != cell)
  {
    s += std::string(" (") + kind + " " + std::to_string(entity) + ")";
  }
  return s;
}

// Reads a grid's points, weights, degrees and entity ids with every index and array
// length checked first: a file is data from outside, and a cell naming a point that is
// not there must be an error that names both, never a read past an array's end.
struct GridAccess
{
  vtkUnstructuredGrid* grid;
  vtkIdType pointCount = 0;
  vtkDataArray* weights = nullptr;
  vtkDataArray* degrees = nullptr;
  vtkDataArray* entities = nullptr;

  GridAccess(vtkUnstructuredGrid* g, const char* entityArray)
    : grid(g)
  {
    if (!g || g->GetNumberOfCells() == 0)
    {
      fail("empty input: the boundary grid has no cells");
    }
    pointCount = g->GetPoints() ? g->GetNumberOfPoints() : 0;
    if (pointCount == 0)
    {
      fail("the boundary grid has ", g->GetNumberOfCells(), " cells but no points");
    }
    // By name, or as the attribute VTK's own Bézier cells use.
    weights = g->GetPointData()->GetArray(arrays::RationalWeights);
    weights = weights ? weights : g->GetPointData()->GetRationalWeights();
    degrees = g->GetCellData()->GetArray(arrays::HigherOrderDegrees);
    degrees = degrees ? degrees : g->GetCellData()->GetHigherOrderDegrees();
    entities = g->GetCellData()->GetArray(entityArray);
    const vtkIdType cells = g->GetNumberOfCells();
    if (weights && weights->GetNumberOfTuples() < pointCount)
    {
      fail("point data ", arrays::RationalWeights, " has ", weights->GetNumberOfTuples(),
        " values for ", pointCount, " points");
    }
    if (degrees && degrees->GetNumberOfTuples() < cells)
    {
      fail("cell data ", arrays::HigherOrderDegrees, " has ", degrees->GetNumberOfTuples(),
        " values for ", cells, " cells");
    }
    if (entities && entities->GetNumberOfTuples() < cells)
    {
      fail("cell data ", entityArray, " has ", entities->GetNumberOfTuples(), " values for ",
        cells, " cells");
    }
  }

  int entity(vtkIdType cell) const
  {
    if (!entities)
      return static_cast<int>(std::min<vtkIdType>(cell, std::numeric_limits<int>::max()));
    const double e = entities->GetComponent(cell, 0);
    // Out of int's range or not an integer: keep the cell's own index.
    return (e >= -1.0 && e <= std::numeric_limits<int>::max() && e == std::floor(e))
      ? static_cast<int>(e)
      : static_cast<int>(std::min<vtkIdType>(cell, std::numeric_limits<int>::max()));
  }

  /// The cell's points as homogeneous control points, in the cell's own order, with the
  /// weights divided by the cell's largest (the curve or patch is unchanged; the
  /// homogeneous coordinates stay finite whatever the weights' scale).
  Vec4List cellPoints(vtkIdList* ids, const std::string& where) const
  {
    const vtkIdType n = ids->GetNumberOfIds();
    std::vector<double> w(n, 1.0);
    double largest = 0.0;
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType id = ids->GetId(k);
      if (id < 0 || id >= pointCount)
      {
        fail(where, ": its point ", k, " is point id ", id, ", but the grid has ", pointCount,
          " points (ids 0 to ", pointCount - 1, ")");
      }
      w[k] = weights ? weights->GetComponent(id, 0) : 1.0;
      if (!std::isfinite(w[k]) || !(w[k] > 0.0))
      {
        fail(where, ": point ", id, " has weight ", w[k], " (", arrays::RationalWeights,
          " must be positive and finite)");
      }
      largest = std::max(largest, w[k]);
    }
    Vec4List h(n);
    for (vtkIdType k = 0; k < n; ++k)
    {
      double x[3];
      grid->GetPoint(ids->GetId(k), x);
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      {
        fail(where, ": point ", ids->GetId(k), " has a NaN or infinite coordinate");
      }
      h[k] = homogeneous(Vec3(x[0], x[1], x[2]), w[k] / largest);
    }
    return h;
  }

  /// The degree stored for the cell (component 0 or 1), or `fallback` without the array;
  /// an entry that is not an integer in [1, MaximumDegree] is an error naming the cell.
  int degree(vtkIdType cell, int component, int fallback, const std::string& where) const
  {
    if (!degrees)
      return fallback;
    if (component >= degrees->GetNumberOfComponents())
      return fallback;
    const double d = degrees->GetComponent(cell, component);
    if (!(d >= 1.0 && d <= MaximumDegree) || d != std::floor(d))
    {
      fail(where, ": ", arrays::HigherOrderDegrees, " gives degree ", d,
        " (a degree must be an integer from 1 to ", MaximumDegree, ")");
    }
    return static_cast<int>(d);
  }

  static constexpr int MaximumDegree = 32;
};
} // namespace

bool gridHasSurfaceCells(vtkUnstructuredGrid* grid)
{
  for (vtkIdType c = 0; grid && c < grid->GetNumberOfCells(); ++c)
  {
    switch (grid->GetCellType(c))
    {
      case VTK_BEZIER_QUADRILATERAL:
      case VTK_BEZIER_TRIANGLE:
      case VTK_QUAD:
      case VTK_TRIANGLE:
        return true;
      default:
        break;
    }
  }
  return false;
}

std::vector<CurvePiece> curvePiecesFromGrid(vtkUnstructuredGrid* grid)
{
  const GridAccess g(grid, arrays::EdgeId);
  std::vector<CurvePiece> pieces;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    grid->GetCellPoints(c, ids);
    const int n = static_cast<int>(ids->GetNumberOfIds());
    const int entity = g.entity(c);
    const std::string where = cellName(c, entity, "edge");
    const int type = grid->GetCellType(c);
    if (type == VTK_BEZIER_CURVE)
    {
      if (n < 2 || n > GridAccess::MaximumDegree + 1)
      {
        fail(where, ": a Bezier curve cell needs 2 to ", GridAccess::MaximumDegree + 1,
          " points, it has ", n);
      }
      const int p = g.degree(c, 0, n - 1, where);
      if (p != n - 1)
      {
        fail(where, ": Bezier curve of degree ", p, " has ", n, " points (needs ", p + 1, ")");
      }
      // VTK order: start, end, interior → Bézier order: start, interior…, end.
      const Vec4List v = g.cellPoints(ids, where);
      Vec4List h(n);
      h[0] = v[0];
      h[p] = v[1];
      for (int i = 1; i < p; ++i)
      {
        h[i] = v[i + 1];
      }
      pieces.push_back({ BezierCurve(std::move(h)), entity, ids->GetId(0), ids->GetId(1) });
    }
    else if (type == VTK_LINE || type == VTK_POLY_LINE)
    {
      if (n < 2)
      {
        fail(where, ": a line needs at least 2 points, it has ", n);
      }
      const Vec4List v = g.cellPoints(ids, where);
      for (int i = 0; i + 1 < n; ++i)
      {
        Vec4List h{ v[i], v[i + 1] };
        // Lines are polynomial whatever the weights say.
        h[0] /= h[0].w();
        h[1] /= h[1].w();
        pieces.push_back({ BezierCurve(std::move(h)), entity, ids->GetId(i), ids->GetId(i + 1) });
      }
    }
    else if (type == VTK_VERTEX || type == VTK_POLY_VERTEX)
    {
      continue; // annotations, not boundary
    }
    else
    {
      fail(where, ": cell type ", type,
        " is not a boundary curve (expected VTK_BEZIER_CURVE, VTK_LINE or VTK_POLY_LINE)");
    }
  }
  if (pieces.empty())
  {
    fail("empty input: the grid has no curve cells");
  }
  return pieces;
}

std::vector<PatchPiece> patchPiecesFromGrid(vtkUnstructuredGrid* grid)
{
  const GridAccess g(grid, arrays::FaceId);
  std::vector<PatchPiece> pieces;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    grid->GetCellPoints(c, ids);
    const int n = static_cast<int>(ids->GetNumberOfIds());
    const int entity = g.entity(c);
    const std::string where = cellName(c, entity, "face");
    const int type = grid->GetCellType(c);
    PatchPiece piece;
    piece.entity = entity;
    if (type == VTK_BEZIER_QUADRILATERAL || type == VTK_QUAD)
    {
      int order[2] = { 1, 1 };
      if (type == VTK_BEZIER_QUADRILATERAL)
      {
        const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n)))) - 1;
        order[0] = g.degree(c, 0, side, where);
        order[1] = g.degree(c, 1, side, where);
      }
      if ((order[0] + 1) * (order[1] + 1) != n || order[0] < 1 || order[1] < 1)
      {
        fail(where, ": Bezier quadrilateral of degrees (", order[0], ", ", order[1], ") has ", n,
          " points");
      }
      const Vec4List v = g.cellPoints(ids, where);
      Vec4List net(n);
      for (int i = 0; i <= order[0]; ++i)
      {
        for (int j = 0; j <= order[1]; ++j)
        {
          const int k = type == VTK_QUAD
            ? (i == 0 ? (j == 0 ? 0 : 3) : (j == 0 ? 1 : 2))
            : vtkHigherOrderQuadrilateral::PointIndexFromIJK(i, j, order);
          net[i * (order[1] + 1) + j] = v[k];
        }
      }
      piece.patch = BezierPatch(order[0], order[1], std::move(net));
    }
    else if (type == VTK_BEZIER_TRIANGLE || type == VTK_TRIANGLE)
    {
      // n = (d+1)(d+2)/2
      const int d = static_cast<int>(std::lround((std::sqrt(8.0 * n + 1.0) - 3.0) / 2.0));
      if ((d + 1) * (d + 2) / 2 != n || d < 1 || d > GridAccess::MaximumDegree)
      {
        fail(where, ": a Bezier triangle cannot have ", n, " points");
      }
      const Vec4List v = g.cellPoints(ids, where);
      TriangleNet tri;
      tri.degree = d;
      tri.points.resize(n);
      for (int i = 0; i <= d; ++i)
      {
        for (int j = 0; i + j <= d; ++j)
        {
          // VTK's barycentric index (i, j, k): powers of the weights of vertices 1, 2, 0.
          const vtkIdType b[3] = { i, j, d - i - j };
          const vtkIdType k = vtkHigherOrderTriangle::Index(b, d);
          tri.points[TriangleNet::index(d, i, j)] = v[k];
        }
      }
      piece.triangle = tri;
      piece.patch = BezierPatch::fromTriangle(tri);
    }
    else if (type == VTK_VERTEX || type == VTK_POLY_VERTEX)
    {
      continue;
    }
    else
    {
      fail(where, ": cell type ", type,
        " is not a boundary surface (expected a Bezier or linear quadrilateral or triangle)");
    }
    pieces.push_back(std::move(piece));
  }
  if (pieces.empty())
  {
    fail("empty input: the grid has no surface cells");
  }
  return pieces;
}

// ---------------------------------------------------------------------------------------

struct BoundaryGridBuilder::State
{
  vtkSmartPointer<vtkPoints> points;
  vtkSmartPointer<vtkDoubleArray> weights, degrees, ranges2, ranges4;
  vtkSmartPointer<vtkIntArray> entities;
  std::map<std::array<double, 4>, vtkIdType> shared;
  bool surfaces = false;
};

BoundaryGridBuilder::BoundaryGridBuilder()
  : Grid(vtkSmartPointer<vtkUnstructuredGrid>::New())
  , Impl(std::make_shared<State>())
{
  Impl->points = vtkSmartPointer<vtkPoints>::New();
  Impl->points->SetDataTypeToDouble();
  Grid->SetPoints(Impl->points);
  Grid->AllocateEstimate(64, 4);
  Impl->weights = vtkSmartPointer<vtkDoubleArray>::New();
  Impl->weights->SetName(arrays::RationalWeights);
  // VTK's Bézier cells read the weights and degrees through these attributes.
  Grid->GetPointData()->SetRationalWeights(Impl->weights);
  Impl->degrees = vtkSmartPointer<vtkDoubleArray>::New();
  Impl->degrees->SetName(arrays::HigherOrderDegrees);
  Impl->degrees->SetNumberOfComponents(3);
  Grid->GetCellData()->SetHigherOrderDegrees(Impl->degrees);
  Impl->entities = vtkSmartPointer<vtkIntArray>::New();
  Impl->entities->SetName(arrays::EdgeId);
  Grid->GetCellData()->AddArray(Impl->entities);
  Impl->ranges2 = vtkSmartPointer<vtkDoubleArray>::New();
  Impl->ranges2->SetName(arrays::ParameterRange);
  Impl->ranges2->SetNumberOfComponents(2);
  Impl->ranges4 = vtkSmartPointer<vtkDoubleArray>::New();
  Impl->ranges4->SetName(arrays::ParameterRange);
  Impl->ranges4->SetNumberOfComponents(4);
  Grid->GetCellData()->AddArray(Impl->ranges2);
}

vtkIdType BoundaryGridBuilder::insertPoint(const Vec4& h, bool shareable)
{
  const Vec3 p = euclidean(h);
  const std::array<double, 4> key{ p.x(), p.y(), p.z(), h.w() };
  if (shareable)
  {
    const auto it = Impl->shared.find(key);
    if (it != Impl->shared.end())
    {
      return it->second;
    }
  }
  const vtkIdType id = Impl->points->InsertNextPoint(p.data());
  Impl->weights->InsertNextValue(h.w());
  if (shareable)
  {
    Impl->shared.emplace(key, id);
  }
  return id;
}

void BoundaryGridBuilder::addCellData(int entity, const double* range, int rangeSize, int p, int q)
{
  if ((rangeSize == 2 && Impl->surfaces) ||
    (rangeSize == 4 && !Impl->surfaces && Impl->ranges2->GetNumberOfTuples() > 0))
  {
    fail("a boundary grid holds either curves (2D) or surfaces (3D), not both");
  }
  Impl->degrees->InsertNextTuple3(p, q, 0);
  Impl->entities->InsertNextValue(entity);
  if (rangeSize == 4 && !Impl->surfaces)
  {
    // The first surface cell switches the grid to surface arrays.
    Impl->surfaces = true;
    Impl->entities->SetName(arrays::FaceId);
    Grid->GetCellData()->RemoveArray(arrays::ParameterRange);
    Grid->GetCellData()->AddArray(Impl->ranges4);
  }
  (rangeSize == 4 ? Impl->ranges4 : Impl->ranges2)->InsertNextTuple(range);
}

void BoundaryGridBuilder::addCurve(const BezierCurve& curve, int entity, double t0, double t1)
{
  const int p = curve.degree();
  const Vec4List& h = curve.homogeneousPoints();
  std::vector<vtkIdType> ids;
  ids.push_back(insertPoint(h[0], true));
  ids.push_back(insertPoint(h[p], true));
  for (int i = 1; i < p; ++i)
  {
    ids.push_back(insertPoint(h[i], false));
  }
  Grid->InsertNextCell(VTK_BEZIER_CURVE, static_cast<vtkIdType>(ids.size()), ids.data());
  const double range[2] = { t0, t1 };
  addCellData(entity, range, 2, p, 0);
}

void BoundaryGridBuilder::addPatch(
  const BezierPatch& patch, int entity, double u0, double u1, double v0, double v1)
{
  const int order[2] = { patch.degreeU(), patch.degreeV() };
  std::vector<vtkIdType> ids((order[0] + 1) * (order[1] + 1));
  for (int i = 0; i <= order[0]; ++i)
  {
    for (int j = 0; j <= order[1]; ++j)
    {
      ids[vtkHigherOrderQuadrilateral::PointIndexFromIJK(i, j, order)] =
        insertPoint(patch.homogeneousPoint(i, j), false);
    }
  }
  Grid->InsertNextCell(VTK_BEZIER_QUADRILATERAL, static_cast<vtkIdType>(ids.size()), ids.data());
  const double range[4] = { u0, u1, v0, v1 };
  addCellData(entity, range, 4, order[0], order[1]);
}

void BoundaryGridBuilder::addTriangle(const TriangleNet& tri, int entity)
{
  const int d = tri.degree;
  std::vector<vtkIdType> ids(tri.points.size());
  for (int i = 0; i <= d; ++i)
  {
    for (int j = 0; i + j <= d; ++j)
    {
      const vtkIdType b[3] = { i, j, d - i - j };
      ids[vtkHigherOrderTriangle::Index(b, d)] = insertPoint(tri.at(i, j), false);
    }
  }
  Grid->InsertNextCell(VTK_BEZIER_TRIANGLE, static_cast<vtkIdType>(ids.size()), ids.data());
  const double range[4] = { 0, 1, 0, 1 };
  addCellData(entity, range, 4, d, d);
}

void BoundaryGridBuilder::addShape(const Shape& shape)
{
  for (size_t e = 0; e < shape.curves.size(); ++e)
  {
    shape.curves[e].validate("curve " + std::to_string(e));
    for (const BezierSpan& s : extractBezier(shape.curves[e]))
    {
      addCurve(s.curve, static_cast<int>(e), s.t0, s.t1);
    }
  }
  for (size_t e = 0; e < shape.surfaces.size(); ++e)
  {
    shape.surfaces[e].validate("surface " + std::to_string(e));
    for (const BezierPatchSpan& s : extractBezier(shape.surfaces[e]))
    {
      addPatch(s.patch, static_cast<int>(e), s.u0, s.u1, s.v0, s.v1);
    }
  }
}

FaceLabels::FaceLabels(const Boundary3D& boundary)
  : B(boundary)
{
  std::map<int, int> count;
  for (const Face3D& f : boundary.faces())
    if (f.entity >= 0)
      ++count[f.entity];
  for (const Face3D& f : boundary.faces())
    EntityFaces.push_back(f.entity >= 0 ? count[f.entity] : 1);
}

std::string FaceLabels::entity(int face) const
{
  const Face3D& f = B.faces()[face];
  return std::to_string(f.entity >= 0 ? f.entity : f.piece);
}

std::string FaceLabels::face(int face) const
{
  return EntityFaces[face] > 1 ? entity(face) + ":" + std::to_string(B.faces()[face].piece) : entity(face);
}

std::string FaceLabels::generator(const std::vector<int>& faces) const
{
  std::string out;
  for (int f : faces)
    out += (out.empty() ? "" : "/") + face(f);
  return out;
}

std::string FaceLabels::edge(int edge) const
{
  const Edge3D& e = B.edges()[edge];
  return face(e.faceA) + "/" + face(e.faceB);
}

} // namespace exactmat
