// vtkMAT25DFilter through the VTK pipeline, checked against the solid vtkNURBSSource
// sweeps (exact Bézier faces, read back from the grid independently of the filter).
#include "vtkExactMATArrayNames.h"
#include "vtkMAT25DFilter.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkNURBSSource.h"

#include "TestHelpers.h"
#include "geometry/BoundingVolumeHierarchy.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

using namespace exactmat;

namespace
{
struct Pipeline
{
  vtkNew<vtkNURBSSource> profile, solid;
  vtkNew<vtkMAT25DFilter> mat;

  Pipeline(const char* shape, bool revolve, double span, const double axis[3] = nullptr)
  {
    profile->SetShapeName(shape);
    solid->SetShapeName(shape);
    mat->SetInputConnection(profile->GetOutputPort());
    if (revolve)
    {
      mat->SetSweepTypeToRevolution();
      mat->SetAngle(span);
      solid->SetSweep(vtkNURBSSource::SweepRevolution);
      solid->SetSweepAngle(span);
      if (axis)
      {
        mat->SetAxisOrigin(const_cast<double*>(axis));
        solid->SetSweepAxisOrigin(const_cast<double*>(axis));
      }
    }
    else
    {
      mat->SetLength(span);
      solid->SetSweep(vtkNURBSSource::SweepExtrusion);
      solid->SetLength(span);
    }
  }
};
} // namespace

TEST(vtkMAT25DFilter, ExtrudedRectangleIsTheBoxMAT)
{
  Pipeline p("rectangle", false, 3.0);
  p.mat->Update();
  vtkPolyData* out = p.mat->GetOutput();
  EXPECT_EQ(p.mat->GetNumberOfJunctions(), 4);
  EXPECT_EQ(p.mat->GetNumberOfSeams(), 12);
  EXPECT_EQ(out->GetNumberOfVerts(), 4);
  EXPECT_GT(out->GetNumberOfPolys(), 100);
  for (const char* name : { arrays::Radius, arrays::PointType, arrays::Touchpoints })
    EXPECT_NE(out->GetPointData()->GetArray(name), nullptr) << name;
  for (const char* name : { arrays::ElementType, arrays::ElementId, arrays::SegmentId })
    EXPECT_NE(out->GetCellData()->GetArray(name), nullptr) << name;
  auto* governors = vtkStringArray::SafeDownCast(out->GetCellData()->GetAbstractArray(arrays::Governors));
  ASSERT_NE(governors, nullptr);
  // Junction vertices come first: a profile face and three sides.
  const std::string first = governors->GetValue(0);
  EXPECT_TRUE(first.rfind("start,", 0) == 0 || first.rfind("end,", 0) == 0) << first;
  EXPECT_EQ(std::count(first.begin(), first.end(), ','), 3) << first;
  // The filter's own verification and an independent one against the source's solid.
  EXPECT_LE(p.mat->GetMaximumVerifiedError(), 1e-9);
  EXPECT_EQ(p.mat->GetNumberOfTouchpointMismatches(), 0);
  EXPECT_GT(p.mat->GetNumberOfVerifiedPoints(), 100);
  p.solid->Update();
  EXPECT_LE(worstRadiusError(p.solid->GetOutput(), out, 3), 1e-9);
}

TEST(vtkMAT25DFilter, RevolvedProfilesAgainstTheSweptSolid)
{
  const double axis[3] = { -3.0, 0.0, 0.0 };
  for (const auto& [shape, angle] : { std::pair<const char*, double>{ "rectangle", 120.0 },
         { "rectangle", 360.0 }, { "ellipse", 120.0 }, { "ellipse", 360.0 },
         { "plate-with-holes", 120.0 } })
  {
    Pipeline p(shape, true, angle, axis);
    p.mat->SetSheetResolution(0.05);
    p.mat->SetMaximumSheetPointsVerified(200);
    p.mat->Update();
    p.solid->Update();
    ASSERT_GT(p.mat->GetOutput()->GetNumberOfPoints(), 0) << shape << " " << angle;
    EXPECT_LE(p.mat->GetMaximumVerifiedError(), 1e-9) << shape << " " << angle;
    EXPECT_EQ(p.mat->GetNumberOfTouchpointMismatches(), 0) << shape << " " << angle;
    EXPECT_LE(worstRadiusError(p.solid->GetOutput(), p.mat->GetOutput(), 17), 1e-9)
      << shape << " " << angle;
    if (angle == 360.0)
    {
      EXPECT_EQ(p.mat->GetNumberOfJunctions(), 0) << shape;
    }
  }
}

TEST(vtkMAT25DFilter, ExtrudedProfilesAgainstTheSweptSolid)
{
  for (const char* shape : { "l-shape", "annulus", "plate-with-holes", "star" })
  {
    Pipeline p(shape, false, 4.0);
    p.mat->SetSheetResolution(0.05);
    p.mat->Update();
    p.solid->Update();
    EXPECT_LE(p.mat->GetMaximumVerifiedError(), 1e-9) << shape;
    EXPECT_EQ(p.mat->GetNumberOfTouchpointMismatches(), 0) << shape;
    EXPECT_LE(worstRadiusError(p.solid->GetOutput(), p.mat->GetOutput(), 7), 1e-9) << shape;
  }
}

// Shorter than 2·Rmax: the mid-sheet, checked against the source's solid.
TEST(vtkMAT25DFilter, ShortSpansAgainstTheSweptSolid)
{
  const double axis[3] = { -3.0, 0.0, 0.0 };
  for (const auto& [shape, revolve, span] : { std::tuple<const char*, bool, double>{ "rectangle", false, 1.5 },
         { "plate-with-holes", false, 0.5 }, { "ellipse", true, 30.0 } })
  {
    Pipeline p(shape, revolve, span, axis);
    p.mat->SetSheetResolution(0.05);
    p.mat->SetMaximumSheetPointsVerified(300);
    p.mat->Update();
    p.solid->Update();
    EXPECT_LE(p.mat->GetMaximumVerifiedError(), 1e-9) << shape;
    EXPECT_EQ(p.mat->GetNumberOfTouchpointMismatches(), 0) << shape;
    EXPECT_LE(worstRadiusError(p.solid->GetOutput(), p.mat->GetOutput(), 11), 1e-9) << shape;
  }
}

TEST(vtkMAT25DFilter, ErrorsNameTheProblem)
{
  auto message = [](vtkMAT25DFilter* f) {
    auto errors = ErrorRecorder::watch(f);
    f->Update();
    return errors->Messages;
  };
  {
    Pipeline p("rectangle", false, 0.0);
    const std::string m = message(p.mat);
    EXPECT_NE(m.find("length must be positive"), std::string::npos) << m;
    EXPECT_EQ(p.mat->GetOutput()->GetNumberOfPoints(), 0);
  }
  {
    Pipeline p("rectangle", true, 90.0); // the y axis crosses the rectangle
    EXPECT_NE(message(p.mat).find("crosses the profile"), std::string::npos);
  }
  {
    vtkNew<vtkNURBSSource> box;
    box->SetShapeName("box");
    vtkNew<vtkMAT25DFilter> f;
    f->SetInputConnection(box->GetOutputPort());
    EXPECT_NE(message(f).find("surface cells"), std::string::npos);
  }
  {
    vtkNew<vtkNURBSSource> s;
    s->SetShapeName("box");
    s->SetSweep(vtkNURBSSource::SweepExtrusion);
    auto errors = ErrorRecorder::watch(s);
    s->Update();
    EXPECT_NE(errors->Messages.find("only 2D shapes"), std::string::npos) << errors->Messages;
  }
}
