// vtkMAT3DFilter through the VTK pipeline, checked against the exact faces vtkNURBSSource
// makes (read back from the grid independently of the filter).
#include "vtkExactMATArrayNames.h"
#include "vtkMAT3DFilter.h"
#include "vtkNURBSSource.h"

#include "TestHelpers.h"

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTransform.h>
#include <vtkTransformFilter.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace exactmat;

TEST(vtkMAT3DFilter, BoxGivesTheClosedFormGraph)
{
  // Box 4 × 3 × 2 centred at the origin: junctions (±1, ±0.5, 0) with radius 1.
  vtkNew<vtkNURBSSource> box;
  box->SetShapeName("box");
  box->SetWidth(4.0);
  box->SetHeight(3.0);
  box->SetLength(2.0);
  vtkNew<vtkMAT3DFilter> mat;
  mat->SetInputConnection(box->GetOutputPort());
  auto errors = ErrorRecorder::watch(mat);
  mat->Update();
  ASSERT_TRUE(errors->Messages.empty()) << errors->Messages;
  vtkPolyData* out = mat->GetOutput();
  EXPECT_EQ(mat->GetNumberOfJunctions(), 4);
  EXPECT_EQ(mat->GetNumberOfSeams(), 12);
  EXPECT_EQ(out->GetNumberOfVerts(), 4);
  EXPECT_EQ(out->GetNumberOfLines(), 12);
  EXPECT_TRUE(mat->GetVerificationPassed());
  EXPECT_LE(mat->GetMaximumVerifiedError(), 1e-9);
  EXPECT_EQ(mat->GetNumberOfTouchpointMismatches(), 0);
  EXPECT_EQ(mat->GetNumberOfVerifiedPoints(), out->GetNumberOfPoints());
  EXPECT_LE(worstRadiusError(box->GetOutput(), out, 1), 1e-9);
  vtkDataArray* radius = out->GetPointData()->GetArray(arrays::Radius);
  vtkDataArray* type = out->GetPointData()->GetArray(arrays::PointType);
  vtkDataArray* touch = out->GetPointData()->GetArray(arrays::Touchpoints);
  ASSERT_TRUE(radius && type && touch);
  int junctions = 0, ends = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    if (type->GetTuple1(i) == 2)
    {
      ++junctions;
      EXPECT_NEAR(std::abs(x[0]), 1.0, 1e-12);
      EXPECT_NEAR(std::abs(x[1]), 0.5, 1e-12);
      EXPECT_NEAR(x[2], 0.0, 1e-12);
      EXPECT_NEAR(radius->GetTuple1(i), 1.0, 1e-12);
      EXPECT_EQ(touch->GetTuple1(i), 4);
    }
    else if (type->GetTuple1(i) == 3)
    {
      ++ends;
      EXPECT_EQ(radius->GetTuple1(i), 0.0);
    }
    else
      EXPECT_EQ(touch->GetTuple1(i), 3);
  }
  EXPECT_EQ(junctions, 4);
  EXPECT_EQ(ends, 8);
  auto* governors = vtkStringArray::SafeDownCast(out->GetCellData()->GetAbstractArray(arrays::Governors));
  ASSERT_TRUE(governors);
  EXPECT_EQ(governors->GetNumberOfTuples(), 16);
  EXPECT_NE(out->GetFieldData()->GetArray(arrays::VerificationStatus), nullptr);
  // The sheets: 13 face pairs; the middle one (bottom and top faces) is bounded by the four
  // seams between the junctions and no convex edge.
  EXPECT_EQ(mat->GetNumberOfSheets(), 13);
  auto* pairs = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray(arrays::SheetGovernors));
  auto* seams = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray(arrays::SheetSeams));
  auto* edges = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray(arrays::SheetConvexEdges));
  ASSERT_TRUE(pairs && seams && edges);
  ASSERT_EQ(pairs->GetNumberOfValues(), 13);
  int middle = 0;
  for (vtkIdType i = 0; i < pairs->GetNumberOfValues(); ++i)
    if (edges->GetValue(i).empty())
    {
      ++middle;
      std::istringstream ids(seams->GetValue(i));
      int id = 0, count = 0;
      while (ids >> id)
      {
        ++count;
        EXPECT_GE(id, 4); // seam elements follow the 4 junctions
        EXPECT_LT(id, 16);
      }
      EXPECT_EQ(count, 4);
    }
  EXPECT_EQ(middle, 1);
}

TEST(vtkMAT3DFilter, PillowMovedFarAwayIsTheSame)
{
  // The free-form pillow, and the same solid rotated and moved to 1e6 × its size: one
  // junction of six touchpoints, eight seams, verified, radius the same.
  double reference = 0.0;
  for (const double offset : { 0.0, 3e6 })
  {
    vtkNew<vtkNURBSSource> pillow;
    pillow->SetShapeName("pillow");
    vtkNew<vtkTransform> motion;
    motion->Translate(offset, -0.5 * offset, 0.25 * offset);
    motion->RotateWXYZ(30.0, 1.0, 2.0, 3.0);
    vtkNew<vtkTransformFilter> moved;
    moved->SetTransform(motion);
    moved->SetInputConnection(pillow->GetOutputPort());
    moved->Update();
    vtkNew<vtkMAT3DFilter> mat;
    mat->SetInputConnection(moved->GetOutputPort());
    auto errors = ErrorRecorder::watch(mat);
    mat->Update();
    ASSERT_TRUE(errors->Messages.empty()) << offset << ": " << errors->Messages;
    EXPECT_EQ(mat->GetNumberOfJunctions(), 1);
    EXPECT_EQ(mat->GetNumberOfSeams(), 8);
    EXPECT_TRUE(mat->GetVerificationPassed()) << offset;
    vtkPolyData* out = mat->GetOutput();
    EXPECT_LE(worstRadiusError(vtkUnstructuredGrid::SafeDownCast(moved->GetOutput()), out, 3), 1e-9);
    vtkDataArray* type = out->GetPointData()->GetArray(arrays::PointType);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      if (type->GetTuple1(i) == 2)
      {
        const double r = out->GetPointData()->GetArray(arrays::Radius)->GetTuple1(i);
        if (offset == 0.0)
          reference = r;
        else
          EXPECT_NEAR(r, reference, 1e-9 * reference);
      }
  }
}

// The notched cube (edge 4, centred, the (+, +, +) eighth cut away): three reflex edges and
// a reflex corner at the origin. Governors name a reflex edge by its two faces' ids and the
// corner by its three, joined by "/"; the diagonal seam meets the corner at the junction
// k (1, 1, 1) − (2, 2, 2), radius k = 2√3 / (1 + √3).
TEST(vtkMAT3DFilter, NotchedCubeNamesItsReflexGenerators)
{
  vtkNew<vtkNURBSSource> cube;
  cube->SetShapeName("notched-cube");
  vtkNew<vtkMAT3DFilter> mat;
  mat->SetInputConnection(cube->GetOutputPort());
  auto errors = ErrorRecorder::watch(mat);
  mat->Update();
  ASSERT_TRUE(errors->Messages.empty()) << errors->Messages;
  vtkPolyData* out = mat->GetOutput();
  EXPECT_EQ(mat->GetNumberOfJunctions(), 7);
  EXPECT_TRUE(mat->GetVerificationPassed());
  EXPECT_EQ(mat->GetNumberOfTouchpointMismatches(), 0);
  EXPECT_LE(worstRadiusError(cube->GetOutput(), out, 1), 1e-9);
  auto* governors = vtkStringArray::SafeDownCast(out->GetCellData()->GetAbstractArray(arrays::Governors));
  ASSERT_TRUE(governors);
  int edgeTokens = 0, cornerTokens = 0;
  for (vtkIdType c = 0; c < governors->GetNumberOfTuples(); ++c)
  {
    std::stringstream list(governors->GetValue(c));
    std::string token;
    while (std::getline(list, token, ','))
    {
      const auto slashes = std::count(token.begin(), token.end(), '/');
      edgeTokens += slashes == 1;
      cornerTokens += slashes == 2;
    }
  }
  EXPECT_GT(edgeTokens, 0);
  EXPECT_GT(cornerTokens, 0);
  const double k = 2.0 * std::sqrt(3.0) / (1.0 + std::sqrt(3.0));
  vtkDataArray* radius = out->GetPointData()->GetArray(arrays::Radius);
  vtkDataArray* type = out->GetPointData()->GetArray(arrays::PointType);
  int diagonal = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    if (type->GetTuple1(i) == 2 && std::abs(radius->GetTuple1(i) - k) < 1e-9)
    {
      ++diagonal;
      for (double c : x)
        EXPECT_NEAR(c, k - 2.0, 1e-9);
    }
  }
  EXPECT_EQ(diagonal, 1);
  // The touchpoints: each at distance Radius from its point.
  vtkDataArray* feet[3] = { out->GetPointData()->GetArray(arrays::Footpoint0),
    out->GetPointData()->GetArray(arrays::Footpoint1), out->GetPointData()->GetArray(arrays::Footpoint2) };
  ASSERT_TRUE(feet[0] && feet[1] && feet[2]);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3], f[3];
    out->GetPoint(i, x);
    for (vtkDataArray* foot : feet)
    {
      foot->GetTuple(i, f);
      EXPECT_NEAR(std::sqrt(vtkMath::Distance2BetweenPoints(x, f)), radius->GetTuple1(i), 1e-9) << i;
    }
  }
}

TEST(vtkMAT3DFilter, UnsupportedAndWrongInputSayWhy)
{
  auto message = [](vtkAlgorithm* source) {
    vtkNew<vtkMAT3DFilter> mat;
    mat->SetInputConnection(source->GetOutputPort());
    auto errors = ErrorRecorder::watch(mat);
    mat->Update();
    EXPECT_EQ(mat->GetOutput()->GetNumberOfPoints(), 0);
    return errors->Messages;
  };
  vtkNew<vtkNURBSSource> extrusion, rectangle;
  // (A blob extruded: its sheets end in fin points, which are not traced yet.)
  extrusion->SetShapeName("extrusion");
  rectangle->SetShapeName("rectangle");
  const std::string c = message(extrusion);
  EXPECT_NE(c.find("no seam touches"), std::string::npos) << c;
  const std::string r = message(rectangle);
  EXPECT_NE(r.find("no surface cells"), std::string::npos) << r;
}
