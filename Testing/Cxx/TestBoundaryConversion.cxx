// The conversion agrees with VTK's own evaluation of its Bézier cells, and is exact.
#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkNURBSSource.h"

#include "common/InputError.h"

#include <vtkBezierCurve.h>
#include <vtkBezierQuadrilateral.h>
#include <vtkBezierTriangle.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkGenericCell.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace exactmat;

namespace
{
// Point of cell c at parametric coordinates, as VTK evaluates it (with rational weights).
Vec3 vtkEvaluate(vtkUnstructuredGrid* grid, vtkIdType c, double r, double s)
{
  vtkNew<vtkGenericCell> cell;
  grid->GetCell(c, cell);
  double pc[3] = { r, s, 0 }, x[3];
  std::vector<double> w(cell->GetNumberOfPoints());
  int sub = 0;
  cell->EvaluateLocation(sub, pc, x, w.data());
  return Vec3(x[0], x[1], x[2]);
}

constexpr double AgreementTolerance = 1e-13; // relative to the shape size
} // namespace

TEST(BoundaryConversion, CurvesAgreeWithVTKBezierCurves)
{
  for (const char* name : { "circle", "blob", "rounded-rectangle", "spiral" })
  {
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(name);
    source->Update();
    vtkUnstructuredGrid* grid = source->GetOutput();
    const std::vector<CurvePiece> pieces = curvePiecesFromGrid(grid);
    ASSERT_EQ(static_cast<vtkIdType>(pieces.size()), grid->GetNumberOfCells());
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
      for (double t : { 0.0, 0.21, 0.5, 0.93, 1.0 })
        EXPECT_LT((vtkEvaluate(grid, c, t, 0) - pieces[c].curve.evaluate(t)).norm(), AgreementTolerance * 10)
          << name << " cell " << c << " t " << t;
  }
}

TEST(BoundaryConversion, PatchesAgreeWithVTKBezierQuadrilaterals)
{
  for (const char* name : { "cylinder", "pillow", "revolution" })
  {
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(name);
    source->Update();
    vtkUnstructuredGrid* grid = source->GetOutput();
    const std::vector<PatchPiece> pieces = patchPiecesFromGrid(grid);
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
      for (double u : { 0.0, 0.3, 1.0 })
        for (double v : { 0.0, 0.6, 1.0 })
          EXPECT_LT((vtkEvaluate(grid, c, u, v) - pieces[c].patch.evaluate(u, v)).norm(), AgreementTolerance * 10)
            << name << " cell " << c;
  }
}

TEST(BoundaryConversion, TrianglesAgreeWithVTKBezierTriangles)
{
  // A rational quadratic triangle written by the builder, read back, evaluated by VTK.
  TriangleNet tri;
  tri.degree = 2;
  tri.points.resize(6);
  auto set = [&](int i, int j, Vec3 p, double w) { tri.points[TriangleNet::index(2, i, j)] = homogeneous(p, w); };
  set(0, 0, Vec3(0, 0, 0), 1.0);
  set(1, 0, Vec3(0.5, -0.1, 0.2), 0.8);
  set(2, 0, Vec3(1, 0, 0), 1.0);
  set(0, 1, Vec3(-0.1, 0.5, 0.1), 1.4);
  set(1, 1, Vec3(0.55, 0.55, 0.3), 0.9);
  set(0, 2, Vec3(0, 1, 0), 1.0);
  BoundaryGridBuilder builder;
  builder.addTriangle(tri, 3);
  vtkUnstructuredGrid* grid = builder.grid();
  ASSERT_EQ(grid->GetCellType(0), VTK_BEZIER_TRIANGLE);
  const std::vector<PatchPiece> pieces = patchPiecesFromGrid(grid);
  ASSERT_TRUE(pieces[0].triangle.has_value());
  EXPECT_EQ(pieces[0].entity, 3);
  for (double r : { 0.0, 0.2, 0.5 })
    for (double s : { 0.0, 0.3, 0.5 })
    {
      // VTK (r, s) ↔ our tensor form (u = r, v = s / (1 − r)).
      const Vec3 ours = pieces[0].patch.evaluate(r, r < 1 ? s / (1 - r) : 0);
      EXPECT_LT((vtkEvaluate(grid, 0, r, s) - ours).norm(), 1e-14) << r << " " << s;
    }
}

TEST(BoundaryConversion, VTKXMLRoundTripIsBitExact)
{
  for (const char* name : { "plate-with-holes", "cylinder" })
  {
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(name);
    source->Update();
    const std::string file = std::string(EXACTMAT_TEST_OUTPUT) + "/roundtrip-" + name + ".vtu";
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputConnection(source->GetOutputPort());
    writer->SetFileName(file.c_str());
    writer->SetDataModeToBinary();
    ASSERT_EQ(writer->Write(), 1);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkUnstructuredGrid* a = source->GetOutput();
    vtkUnstructuredGrid* b = reader->GetOutput();
    ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
    ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
    if (gridHasSurfaceCells(a))
    {
      const auto pa = patchPiecesFromGrid(a), pb = patchPiecesFromGrid(b);
      for (size_t k = 0; k < pa.size(); ++k)
        EXPECT_TRUE(pa[k].patch.homogeneousNet() == pb[k].patch.homogeneousNet());
    }
    else
    {
      const auto pa = curvePiecesFromGrid(a), pb = curvePiecesFromGrid(b);
      for (size_t k = 0; k < pa.size(); ++k)
      {
        EXPECT_TRUE(pa[k].curve.homogeneousPoints() == pb[k].curve.homogeneousPoints());
        EXPECT_EQ(pa[k].entity, pb[k].entity);
      }
    }
  }
}

TEST(BoundaryConversion, LinesPolylinesAndQuadsAreDegreeOneEntities)
{
  vtkNew<vtkUnstructuredGrid> g;
  vtkNew<vtkPoints> pts;
  for (auto p : { Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1, 0) })
    pts->InsertNextPoint(p.data());
  g->SetPoints(pts);
  vtkIdType poly[3] = { 0, 1, 2 }, line[2] = { 2, 3 }, back[2] = { 3, 0 };
  g->InsertNextCell(VTK_POLY_LINE, 3, poly);
  g->InsertNextCell(VTK_LINE, 2, line);
  g->InsertNextCell(VTK_LINE, 2, back);
  const auto pieces = curvePiecesFromGrid(g);
  ASSERT_EQ(pieces.size(), 4u);
  const Boundary2D b = Boundary2D::build(pieces);
  EXPECT_NEAR(b.loops()[0].signedArea, 2.0, 1e-15);
  EXPECT_EQ(b.countVertices(VertexKind::Convex), 4);
}

TEST(BoundaryConversion, BadCellsAreNamed)
{
  auto errorOf = [](vtkUnstructuredGrid* g, bool surfaces) {
    try
    {
      if (surfaces)
        patchPiecesFromGrid(g);
      else
        curvePiecesFromGrid(g);
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  vtkNew<vtkUnstructuredGrid> empty;
  EXPECT_NE(errorOf(empty, false).find("empty input"), std::string::npos);

  vtkNew<vtkNURBSSource> source;
  source->SetShapeName("circle");
  source->Update();
  vtkNew<vtkUnstructuredGrid> g;
  g->DeepCopy(source->GetOutput());
  vtkDataArray* w = g->GetPointData()->GetArray(arrays::RationalWeights);
  w->SetComponent(2, 0, -0.5);
  const std::string weight = errorOf(g, false);
  EXPECT_NE(weight.find("has weight -0.5"), std::string::npos) << weight;
  w->SetComponent(2, 0, 1.0);
  g->GetPoints()->SetPoint(3, NAN, 0, 0);
  EXPECT_NE(errorOf(g, false).find("NaN or infinite"), std::string::npos);
  // A volume cell is not a boundary.
  vtkNew<vtkUnstructuredGrid> tet;
  vtkNew<vtkPoints> p4;
  for (int i = 0; i < 4; ++i)
    p4->InsertNextPoint(i == 1, i == 2, i == 3);
  tet->SetPoints(p4);
  vtkIdType ids[4] = { 0, 1, 2, 3 };
  tet->InsertNextCell(VTK_TETRA, 4, ids);
  EXPECT_NE(errorOf(tet, false).find("cell 0: cell type 10 is not a boundary curve"), std::string::npos)
    << errorOf(tet, false);
  EXPECT_NE(errorOf(tet, true).find("is not a boundary surface"), std::string::npos);
}

// Hostile grids (files are data from outside): every point id and array length is checked
// before use — under the sanitizers these read nothing past an array's end — and the error
// names the cell, the id or the array.
TEST(BoundaryConversion, HostileGridsAreCheckedBeforeUse)
{
  auto square = [](vtkIdType badId, int weightCount, int degreeCount, bool points) {
    vtkNew<vtkUnstructuredGrid> g;
    if (points)
    {
      vtkNew<vtkPoints> p;
      p->InsertNextPoint(0, 0, 0);
      p->InsertNextPoint(1, 0, 0);
      p->InsertNextPoint(1, 1, 0);
      p->InsertNextPoint(0, 1, 0);
      g->SetPoints(p);
    }
    for (vtkIdType i = 0; i < 4; ++i)
    {
      const vtkIdType ids[2] = { i, i == 2 && badId != 0 ? badId : (i + 1) % 4 };
      g->InsertNextCell(VTK_BEZIER_CURVE, 2, ids);
    }
    if (weightCount >= 0)
    {
      vtkNew<vtkDoubleArray> w;
      w->SetName(arrays::RationalWeights);
      for (int i = 0; i < weightCount; ++i)
        w->InsertNextValue(1.0);
      g->GetPointData()->AddArray(w);
    }
    if (degreeCount >= 0)
    {
      vtkNew<vtkDoubleArray> d;
      d->SetName(arrays::HigherOrderDegrees);
      d->SetNumberOfComponents(3);
      for (int i = 0; i < degreeCount; ++i)
        d->InsertNextTuple3(1, 0, 0);
      g->GetCellData()->AddArray(d);
    }
    return vtkSmartPointer<vtkUnstructuredGrid>(g);
  };
  auto expectError = [](vtkUnstructuredGrid* g, const std::string& message) {
    try
    {
      curvePiecesFromGrid(g);
      ADD_FAILURE() << "no error, expected '" << message << "'";
    }
    catch (const InputError& e)
    {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  EXPECT_EQ(curvePiecesFromGrid(square(0, 4, 4, true)).size(), 4u);
  expectError(square(7, -1, -1, true), "point id 7");
  expectError(square(-3, -1, -1, true), "point id -3");
  expectError(square(1000000000, -1, -1, true), "point id 1000000000");
  expectError(square(0, 2, -1, true), "RationalWeights has 2 values for 4 points");
  expectError(square(0, -1, 1, true), "HigherOrderDegrees has 1 values for 4 cells");
  expectError(square(0, -1, -1, false), "no points");
  // A degree that does not fit in an int must not wrap around to a small one.
  vtkSmartPointer<vtkUnstructuredGrid> huge = square(0, -1, 4, true);
  huge->GetCellData()->GetArray(arrays::HigherOrderDegrees)->SetComponent(1, 0, 4294967297.0);
  expectError(huge, "degree 4294967297");
  huge->GetCellData()->GetArray(arrays::HigherOrderDegrees)->SetComponent(1, 0, 1.5);
  expectError(huge, "degree 1.5");
}
