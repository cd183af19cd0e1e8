#include "vtkMAT25DFilter.h"

#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkMATComplexOutput.h"
#include "vtkMATPartResult.h"
#include "vtkMATThreads.h"
#include "vtkMATVerificationReport.h"

#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "mat25d/MAT25D.h"
#include "mat25d/SweptBoundary.h"
#include "medial/Verification.h"
#include "mat2d/Tracer.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <chrono>
#include <limits>
#include <exception>
#include <new>
#include <string>

vtkStandardNewMacro(vtkMAT25DFilter);

vtkMAT25DFilter::vtkMAT25DFilter() = default;
vtkMAT25DFilter::~vtkMAT25DFilter() = default;

namespace
{
using namespace exactmat;

double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// "3,7,start" from governor ids (MAT25D.h numbering): profile edges by their EdgeId.
std::string governorNames(const Boundary2D& profile, const std::vector<int>& governors)
{
  const int edges = static_cast<int>(profile.edges().size());
  std::string out;
  for (int g : governors)
  {
    std::string name;
    if (g < edges)
      name = std::to_string(profile.edges()[g].entity);
    else if (g == edges)
      name = "start";
    else if (g == edges + 1)
      name = "end";
    else
      name = "v" + std::to_string(g - edges - 2);
    out += (out.empty() ? "" : ",") + name;
  }
  return out;
}

} // namespace

void vtkMAT25DFilter::ComputePart(vtkUnstructuredGrid* input, vtkPolyData* output,
  exactmat::PartResult& result, const std::function<void(double)>& progress) const
{
  exactmat::checkParameter("Length", this->Length, 0.0, std::numeric_limits<double>::max());
  exactmat::checkParameter("Angle", this->Angle, 0.0, 360.0);
  exactmat::checkParameter("Tolerance", this->Tolerance, 1e-12, 1e-1);
  exactmat::checkParameter("Step", this->Step, 1e-9, 1e-1);
  exactmat::checkParameter("BranchCheckStep", this->BranchCheckStep, 1e-9, 1.0);
  exactmat::checkParameter("SheetResolution", this->SheetResolution, 1e-4, 0.5);
  exactmat::checkParameter("VerificationTolerance", this->VerificationTolerance, 0.0, 1.0);
  if (exactmat::gridHasSurfaceCells(input))
  {
    exactmat::fail("the input holds surface cells: vtkMAT25DFilter takes the profile "
                   "curves of the solid (use vtkMAT3DFilter for solids given by surfaces)");
  }
  // The whole computation runs in the profile's unit frame (the sweep moved and scaled
  // with it); writeComplex maps back.
  const exactmat::Boundary2D profile =
    exactmat::buildNormalised(exactmat::curvePiecesFromGrid(input));
  const exactmat::Normalisation& frame = profile.userFrame();
  const exactmat::Sweep sweep = this->SweepType == Revolution
    ? exactmat::Sweep::revolution(this->Angle, frame.toUnit(exactmat::Vec3(this->AxisOrigin)),
        exactmat::Vec3(this->AxisDirection))
    : exactmat::Sweep::extrusion(frame.lengthToUnit(this->Length));
  const exactmat::SweepMap map(profile, sweep); // checks the sweep before any work

  auto t0 = std::chrono::steady_clock::now();
  const exactmat::Generators generators(profile);
  exactmat::MAT2DOptions options;
  options.tolerance = this->Tolerance;
  options.fixedStep = this->FixedStep;
  options.step = this->Step;
  options.branchCheckStep = this->BranchCheckStep;
  options.progress = [&progress](double f) { progress(0.5 * f); };
  const exactmat::MedialGraph graph = exactmat::computeMAT2D(generators, options);
  result.measure("ProfileSeconds", secondsSince(t0));

  t0 = std::chrono::steady_clock::now();
  exactmat::MAT25DOptions options3;
  options3.sheetResolution = this->SheetResolution;
  options3.progress = [&progress](double f) { progress(0.5 + 0.3 * f); };
  const exactmat::MedialComplex mat = exactmat::computeMAT25D(generators, graph, map, options3);
  result.measure("ConstructionSeconds", secondsSince(t0));
  exactmat::writeMedialComplex(mat, frame,
    [&profile](const exactmat::MedialElement& e) { return governorNames(profile, e.governors); }, true,
    output);

  using ET = exactmat::MedialElementType;
  result.count("NumberOfJunctions", mat.count(ET::Junction));
  result.count("NumberOfSeams", mat.count(ET::Seam));
  result.count("NumberOfSkeletalEdges", mat.count(ET::SkeletalEdge));
  result.count("NumberOfSheets", mat.count(ET::SweptSheet) + mat.count(ET::ProfileSheet));
  if (this->VerifyOutput)
  {
    const int sheetPoints = mat.countPoints(exactmat::MedialPoint3DType::Sheet) +
      mat.countPoints(exactmat::MedialPoint3DType::ConvexEdge);
    const int stride = this->MaximumSheetPointsVerified > 0
      ? std::max(1, (sheetPoints + this->MaximumSheetPointsVerified - 1) /
            this->MaximumSheetPointsVerified)
      : VTK_INT_MAX;
    const exactmat::SweptBoundary boundary(profile, map);
    const exactmat::MedialVerification v =
      exactmat::verifyMedialComplex(boundary, mat, stride, 1e-15, exactmat::smpParallelFor());
    result.count("NumberOfVerifiedPoints", v.points);
    result.count("NumberOfTouchpointMismatches", v.contactMismatches);
    result.verification = exactmat::outcomeOf(v, this->VerificationTolerance, mat, frame);
  }
}

void vtkMAT25DFilter::PublishFigures(const exactmat::PartResult& figures)
{
  this->NumberOfJunctions = static_cast<int>(figures.get("NumberOfJunctions"));
  this->NumberOfSeams = static_cast<int>(figures.get("NumberOfSeams"));
  this->NumberOfSkeletalEdges = static_cast<int>(figures.get("NumberOfSkeletalEdges"));
  this->NumberOfSheets = static_cast<int>(figures.get("NumberOfSheets"));
  this->NumberOfVerifiedPoints = static_cast<int>(figures.get("NumberOfVerifiedPoints"));
  this->NumberOfTouchpointMismatches =
    static_cast<int>(figures.get("NumberOfTouchpointMismatches"));
  this->ProfileSeconds = figures.get("ProfileSeconds");
  this->ConstructionSeconds = figures.get("ConstructionSeconds");
}

void vtkMAT25DFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SweepType: " << (this->SweepType == Revolution ? "Revolution" : "Extrusion")
     << "\n";
  os << indent << "Length: " << this->Length << "\n";
  os << indent << "Angle: " << this->Angle << "\n";
  os << indent << "AxisOrigin: " << this->AxisOrigin[0] << " " << this->AxisOrigin[1] << " "
     << this->AxisOrigin[2] << "\n";
  os << indent << "AxisDirection: " << this->AxisDirection[0] << " " << this->AxisDirection[1]
     << " " << this->AxisDirection[2] << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "FixedStep: " << this->FixedStep << "\n";
  os << indent << "Step: " << this->Step << "\n";
  os << indent << "BranchCheckStep: " << this->BranchCheckStep << "\n";
  os << indent << "SheetResolution: " << this->SheetResolution << "\n";
  os << indent << "NumberOfJunctions: " << this->NumberOfJunctions << "\n";
}
