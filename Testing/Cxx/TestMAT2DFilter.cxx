// vtkMAT2DFilter through the VTK pipeline: arrays, graph structure, exactness, errors.
#include "vtkExactMATArrayNames.h"
#include "vtkMAT2DFilter.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkNURBSReader.h"
#include "vtkNURBSSource.h"

#include "TestHelpers.h"
#include "mat2d/Generators.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace exactmat;

namespace
{
// Global distance from every output point to the exact input boundary vs its Radius,
// computed from the input independently of the filter; relative to the domain size.
double worstRadiusError(vtkUnstructuredGrid* boundaryGrid, vtkPolyData* mat)
{
  const Boundary2D b = Boundary2D::build(curvePiecesFromGrid(boundaryGrid));
  const Generators g(b);
  vtkDataArray* radius = mat->GetPointData()->GetArray(arrays::Radius);
  double worst = 0.0;
  for (vtkIdType i = 0; i < mat->GetNumberOfPoints(); ++i)
  {
    double x[3];
    mat->GetPoint(i, x);
    const Vec3 local = b.plane().toLocal(Vec3(x[0], x[1], x[2]));
    EXPECT_NEAR(local.z(), 0.0, 1e-12 * b.diagonal());
    worst = std::max(worst, std::abs(g.distance(Vec2(local.x(), local.y())) - radius->GetTuple1(i)));
  }
  return worst / b.diagonal();
}
} // namespace

TEST(vtkMAT2DFilter, EveryCatalogueShapeIsExactAndComplete)
{
  for (const char* name : { "rectangle", "rounded-rectangle", "circle", "ellipse", "annulus",
         "l-shape", "star", "blob", "spiral", "plate-with-holes", "narrow-passage" })
  {
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(name);
    vtkNew<vtkMAT2DFilter> mat;
    mat->SetInputConnection(source->GetOutputPort());
    mat->Update();
    vtkPolyData* out = mat->GetOutput();
    ASSERT_GT(out->GetNumberOfPoints(), 0) << name;
    for (const char* a : { arrays::Radius, arrays::PointType, arrays::Footpoint0, arrays::Footpoint1 })
      ASSERT_NE(out->GetPointData()->GetArray(a), nullptr) << name << " " << a;
    for (const char* a : { arrays::SegmentId, arrays::Generator0, arrays::Generator1 })
      ASSERT_NE(out->GetCellData()->GetArray(a), nullptr) << name << " " << a;
    ASSERT_NE(out->GetCellData()->GetAbstractArray(arrays::Generators), nullptr);
    EXPECT_EQ(out->GetNumberOfLines(), mat->GetNumberOfSegments()) << name;
    EXPECT_LE(worstRadiusError(source->GetOutput(), out), 1e-9) << name;
    EXPECT_LE(mat->GetMaximumVerifiedError(), 1e-9) << name;
    // Footpoints are at distance Radius from their point.
    vtkDataArray* f0 = out->GetPointData()->GetArray(arrays::Footpoint0);
    vtkDataArray* r = out->GetPointData()->GetArray(arrays::Radius);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double x[3], f[3];
      out->GetPoint(i, x);
      f0->GetTuple(i, f);
      EXPECT_NEAR(std::hypot(x[0] - f[0], x[1] - f[1], x[2] - f[2]), r->GetTuple1(i), 1e-9) << name;
    }
  }
}

TEST(vtkMAT2DFilter, TheGraphSharesPointIdsAtBranchPoints)
{
  vtkNew<vtkNURBSSource> source;
  source->SetShapeName("rectangle");
  vtkNew<vtkMAT2DFilter> mat;
  mat->SetInputConnection(source->GetOutputPort());
  mat->Update();
  vtkPolyData* out = mat->GetOutput();
  EXPECT_EQ(mat->GetNumberOfSegments(), 5);
  EXPECT_EQ(mat->GetNumberOfBranchPoints(), 2);
  EXPECT_EQ(mat->GetNumberOfEndPoints(), 4);
  EXPECT_EQ(out->GetNumberOfVerts(), 6);
  // Each branch point (PointType 1) is the end of exactly three polylines.
  vtkDataArray* type = out->GetPointData()->GetArray(arrays::PointType);
  std::vector<int> degree(out->GetNumberOfPoints(), 0);
  vtkCellArray* lines = out->GetLines();
  vtkNew<vtkIdList> ids;
  for (lines->InitTraversal(); lines->GetNextCell(ids);)
  {
    ++degree[ids->GetId(0)];
    ++degree[ids->GetId(ids->GetNumberOfIds() - 1)];
  }
  int branches = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    if (type->GetTuple1(i) == 1)
    {
      EXPECT_EQ(degree[i], 3);
      ++branches;
    }
  }
  EXPECT_EQ(branches, 2);
}

TEST(vtkMAT2DFilter, ADomainOutOfTheXYPlaneGivesItsMATInPlace)
{
  // The L-shape, rotated and shifted, written as JSON: the MAT lies in the same plane.
  const double c = std::cos(0.6), s = std::sin(0.6);
  auto num = [](double v) {
    std::ostringstream os;
    os.precision(17);
    os << v;
    return os.str();
  };
  auto P = [&](double x, double y) {
    // rotate about the x axis, then shift
    return "[" + num(x + 1.0) + "," + num(c * y + 2.0) + "," + num(s * y - 1.0) + "]";
  };
  const double pts[6][2] = { { 0, 0 }, { 4, 0 }, { 4, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } };
  std::string json = "{\"curves\": [";
  for (int i = 0; i < 6; ++i)
  {
    json += std::string(i ? "," : "") + "{\"degree\": 1, \"knots\": [0,0,1,1], \"points\": [" +
      P(pts[i][0], pts[i][1]) + "," + P(pts[(i + 1) % 6][0], pts[(i + 1) % 6][1]) + "]}";
  }
  json += "]}";
  const std::string file = std::string(EXACTMAT_TEST_OUTPUT) + "/tilted-l.json";
  std::ofstream(file) << json;
  vtkNew<vtkNURBSReader> reader;
  reader->SetFileName(file.c_str());
  vtkNew<vtkMAT2DFilter> mat;
  mat->SetInputConnection(reader->GetOutputPort());
  mat->Update();
  EXPECT_EQ(mat->GetNumberOfBranchPoints(), 3);
  EXPECT_LE(worstRadiusError(reader->GetOutput(), mat->GetOutput()), 1e-9);
}

TEST(vtkMAT2DFilter, FixedStepModeReproducesTheThesisSettings)
{
  vtkNew<vtkNURBSSource> source;
  source->SetShapeName("plate-with-holes");
  vtkNew<vtkMAT2DFilter> adaptive, fixed;
  adaptive->SetInputConnection(source->GetOutputPort());
  fixed->SetInputConnection(source->GetOutputPort());
  fixed->FixedStepOn();
  EXPECT_EQ(fixed->GetStep(), 1e-3);
  EXPECT_EQ(fixed->GetBranchCheckStep(), 1e-2);
  adaptive->Update();
  fixed->Update();
  EXPECT_EQ(fixed->GetNumberOfSegments(), adaptive->GetNumberOfSegments());
  EXPECT_EQ(fixed->GetNumberOfBranchPoints(), adaptive->GetNumberOfBranchPoints());
  // About one point per 1e-3 of the size along the MAT.
  EXPECT_GT(fixed->GetOutput()->GetNumberOfPoints(), 5 * adaptive->GetOutput()->GetNumberOfPoints());
  EXPECT_LE(fixed->GetMaximumVerifiedError(), 1e-9);
}

TEST(vtkMAT2DFilter, BadInputFailsWithAClearError)
{
  auto errorsFor = [](vtkUnstructuredGrid* grid) {
    vtkNew<vtkMAT2DFilter> mat;
    mat->SetInputData(grid);
    auto rec = ErrorRecorder::watch(mat);
    mat->Update();
    EXPECT_EQ(mat->GetOutput()->GetNumberOfPoints(), 0);
    return rec->Messages;
  };
  vtkNew<vtkUnstructuredGrid> empty;
  EXPECT_NE(errorsFor(empty).find("empty input"), std::string::npos);
  // An open loop: the rectangle without one side.
  vtkNew<vtkNURBSSource> source;
  source->SetShapeName("rectangle");
  source->Update();
  vtkNew<vtkUnstructuredGrid> open;
  open->DeepCopy(source->GetOutput());
  open->GetCells()->Initialize();
  vtkNew<vtkUnstructuredGrid> three;
  three->SetPoints(source->GetOutput()->GetPoints());
  three->GetPointData()->ShallowCopy(source->GetOutput()->GetPointData());
  three->Allocate(3);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < 3; ++c)
  {
    source->GetOutput()->GetCellPoints(c, ids);
    three->InsertNextCell(source->GetOutput()->GetCellType(c), ids);
  }
  const std::string openError = errorsFor(three);
  EXPECT_NE(openError.find("open loop"), std::string::npos) << openError;
  // A solid is not a planar domain.
  vtkNew<vtkNURBSSource> box;
  box->SetShapeName("box");
  box->Update();
  EXPECT_NE(errorsFor(box->GetOutput()).find("surface cells"), std::string::npos);
}
