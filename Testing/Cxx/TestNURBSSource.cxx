// vtkNURBSSource: every catalogue shape, user-defined NURBS, errors.
#include "vtkNURBSSource.h"

#include "TestHelpers.h"
#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace exactmat;

TEST(vtkNURBSSource, EveryCatalogueShapeProducesAValidBoundary)
{
  vtkNew<vtkNURBSSource> source;
  ASSERT_EQ(vtkNURBSSource::GetNumberOfCatalogueShapes(), 21);
  for (int i = 0; i < vtkNURBSSource::GetNumberOfCatalogueShapes(); ++i)
  {
    const std::string name = vtkNURBSSource::GetCatalogueShapeName(i);
    ASSERT_TRUE(source->SetShapeName(name.c_str()));
    EXPECT_EQ(source->GetShape(), i);
    source->Update();
    vtkUnstructuredGrid* out = source->GetOutput();
    ASSERT_GT(out->GetNumberOfCells(), 0) << name;
    ASSERT_NE(out->GetPointData()->GetArray(arrays::RationalWeights), nullptr);
    ASSERT_NE(out->GetCellData()->GetArray(arrays::HigherOrderDegrees), nullptr);
    ASSERT_NE(out->GetCellData()->GetArray(arrays::ParameterRange), nullptr);
    if (gridHasSurfaceCells(out))
    {
      EXPECT_EQ(out->GetCellType(0), VTK_BEZIER_QUADRILATERAL) << name;
      ASSERT_NE(out->GetCellData()->GetArray(arrays::FaceId), nullptr);
      const Boundary3D b = Boundary3D::build(patchPiecesFromGrid(out));
      EXPECT_GT(b.volume(), 0.0) << name;
    }
    else
    {
      EXPECT_EQ(out->GetCellType(0), VTK_BEZIER_CURVE) << name;
      ASSERT_NE(out->GetCellData()->GetArray(arrays::EdgeId), nullptr);
      const Boundary2D b = Boundary2D::build(curvePiecesFromGrid(out));
      // The source's output is already oriented: nothing is flipped or reversed.
      for (const Loop2D& l : b.loops())
        EXPECT_FALSE(l.flipped) << name;
      for (const Edge2D& e : b.edges())
        EXPECT_FALSE(e.reversed) << name;
    }
  }
}

TEST(vtkNURBSSource, ParametersChangeTheShape)
{
  vtkNew<vtkNURBSSource> source;
  source->SetShapeName("circle");
  source->SetRadius(2.5);
  source->Update();
  const Boundary2D b = Boundary2D::build(curvePiecesFromGrid(source->GetOutput()));
  EXPECT_NEAR(b.loops()[0].signedArea, M_PI * 2.5 * 2.5, 1e-11);
  for (const Edge2D& e : b.edges())
    for (double t : { 0.0, 0.3, 0.77 })
      EXPECT_NEAR(e.curve.evaluate(t).norm(), 2.5, 1e-14);
  EXPECT_STREQ(source->GetShapeName(), "circle");
}

TEST(vtkNURBSSource, UserDefinedCurvesAndSurfaces)
{
  vtkNew<vtkNURBSSource> source;
  source->SetShape(vtkNURBSSource::UserDefined);
  // A closed quadratic NURBS: the unit circle from 9 control points (4 spans).
  const double s = std::sqrt(0.5);
  const double pts[9][2] = { { 1, 0 }, { 1, 1 }, { 0, 1 }, { -1, 1 }, { -1, 0 }, { -1, -1 },
    { 0, -1 }, { 1, -1 }, { 1, 0 } };
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> weights, knots;
  for (int i = 0; i < 9; ++i)
  {
    points->InsertNextPoint(pts[i][0], pts[i][1], 0.0);
    weights->InsertNextValue(i % 2 ? s : 1.0);
  }
  for (double k : { 0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0 })
    knots->InsertNextValue(k);
  source->AddCurve(2, knots, points, weights);
  source->Update();
  vtkUnstructuredGrid* out = source->GetOutput();
  EXPECT_EQ(out->GetNumberOfCells(), 4);
  const Boundary2D b = Boundary2D::build(curvePiecesFromGrid(out));
  EXPECT_NEAR(b.loops()[0].signedArea, M_PI, 1e-12);

  // A bad knot vector is reported with the curve's index, and RequestData fails.
  source->RemoveAllEntities();
  vtkNew<vtkDoubleArray> badKnots;
  for (double k : { 0.0, 0.0, 0.0, 0.5, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0 })
    badKnots->InsertNextValue(k);
  source->AddCurve(2, badKnots, points, weights);
  auto errors = ErrorRecorder::watch(source);
  source->Modified();
  source->Update();
  EXPECT_NE(errors->Messages.find("curve 0: knot vector is not non-decreasing"), std::string::npos)
    << errors->Messages;
  EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0);

  // Surfaces: a tetrahedron of four bilinear patches with one collapsed side each would be
  // contrived; use a unit cube of six bilinear faces given as NURBS.
  source->RemoveAllEntities();
  const double c[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  const int faces[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 2, 3, 7, 6 },
    { 0, 4, 7, 3 }, { 1, 2, 6, 5 } };
  vtkNew<vtkDoubleArray> k01;
  for (double k : { 0.0, 0.0, 1.0, 1.0 })
    k01->InsertNextValue(k);
  for (auto& f : faces)
  {
    vtkNew<vtkPoints> net; // (i, j) with v fastest: a(0,0) d(0,1) b(1,0) c(1,1)
    for (int idx : { f[0], f[3], f[1], f[2] })
      net->InsertNextPoint(c[idx]);
    source->AddSurface(1, 1, k01, k01, 2, 2, net, nullptr);
  }
  errors->Messages.clear();
  source->Update();
  EXPECT_TRUE(errors->Messages.empty()) << errors->Messages;
  const Boundary3D cube = Boundary3D::build(patchPiecesFromGrid(source->GetOutput()));
  EXPECT_NEAR(cube.volume(), 1.0, 1e-14);
  EXPECT_EQ(cube.countEdges(VertexKind::Convex), 12);
}

TEST(vtkNURBSSource, BadShapesAndParametersFailClearly)
{
  vtkNew<vtkNURBSSource> source;
  auto errors = ErrorRecorder::watch(source);
  EXPECT_FALSE(source->SetShapeName("hexagon"));
  EXPECT_NE(errors->Messages.find("unknown shape 'hexagon'"), std::string::npos);
  source->SetShapeName("annulus");
  source->SetInnerRadius(3.0);
  source->Update();
  EXPECT_NE(errors->Messages.find("innerRadius 3 must be less than radius 1"), std::string::npos)
    << errors->Messages;
  source->SetShape(vtkNURBSSource::UserDefined);
  errors->Messages.clear();
  source->Update();
  EXPECT_NE(errors->Messages.find("no entities"), std::string::npos) << errors->Messages;
}
