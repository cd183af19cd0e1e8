#include "vtkMAT3DFilter.h"

#include "vtkMATBoundaryConversion.h"
#include "vtkMATComplexOutput.h"
#include "vtkMATPartResult.h"
#include "vtkMATThreads.h"
#include "vtkMATVerificationReport.h"

#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "mat3d/MAT3D.h"
#include "mat3d/PatchBoundary.h"
#include "medial/Verification.h"

#include "vtkExactMATArrayNames.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <new>
#include <string>

vtkStandardNewMacro(vtkMAT3DFilter);

vtkMAT3DFilter::vtkMAT3DFilter() = default;
vtkMAT3DFilter::~vtkMAT3DFilter() = default;

namespace
{
double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
} // namespace

void vtkMAT3DFilter::ComputePart(vtkUnstructuredGrid* input, vtkPolyData* output,
  exactmat::PartResult& result, const std::function<void(double)>& progress) const
{
  exactmat::checkParameter("Tolerance", this->Tolerance, 1e-12, 1e-1);
  exactmat::checkParameter("MaximumStep", this->MaximumStep, 1e-6, 0.5);
  exactmat::checkParameter("Step", this->Step, 1e-9, 1e-1);
  exactmat::checkParameter("JunctionCheckStep", this->JunctionCheckStep, 1e-9, 1.0);
  exactmat::checkParameter("VerificationTolerance", this->VerificationTolerance, 0.0, 1.0);
  if (!exactmat::gridHasSurfaceCells(input))
    exactmat::fail("the input holds no surface cells: vtkMAT3DFilter takes the faces of a solid "
                   "(use vtkMAT2DFilter for planar domains given by curves)");
  // Everything runs in the solid's unit frame; the output is mapped back.
  const exactmat::Boundary3D boundary = exactmat::buildNormalised(exactmat::patchPiecesFromGrid(input));
  const exactmat::Normalisation& frame = boundary.userFrame();

  auto t0 = std::chrono::steady_clock::now();
  exactmat::MAT3DOptions options;
  options.tolerance = this->Tolerance;
  options.maxStep = this->MaximumStep;
  options.fixedStep = this->FixedStep;
  options.step = this->Step;
  options.junctionCheckStep = this->JunctionCheckStep;
  options.progress = [&progress](double f) { progress(0.8 * f); };
  const exactmat::MAT3D mat = exactmat::computeMAT3D(boundary, options);
  result.measure("TracingSeconds", secondsSince(t0));
  const exactmat::MedialComplex complex = mat.complex();
  const exactmat::FaceLabels labels(boundary);
  auto generatorId = [&mat, &labels](int g) { return labels.generator(mat.generators[g].faces); };
  auto generatorIds = [&generatorId](const exactmat::MedialElement& e) {
    std::string out;
    for (int g : e.governors)
      out += (out.empty() ? "" : ",") + generatorId(g);
    return out;
  };
  exactmat::writeMedialComplex(complex, frame, generatorIds, false, output);
  const int junctions = mat.junctionCount();
  result.count("NumberOfJunctions", junctions);
  result.count("NumberOfSeams", static_cast<int>(mat.seams.size()));
  result.count("NumberOfSkeletalEdges", static_cast<int>(mat.skeletalEdges.size()));
  result.count("NumberOfCentreCurves", static_cast<int>(mat.centreCurves.size()));
  result.count("NumberOfSphereCentres",
    static_cast<int>(std::count_if(mat.nodes.begin(), mat.nodes.end(), [](const exactmat::MAT3DNode& n) {
      return n.sphereCentre;
    })));
  result.count("NumberOfSheets", static_cast<int>(mat.sheets.size()));
  // The sheets' topology, for vtkSheetInterpolator: face pair and bounding elements.
  vtkNew<vtkStringArray> sheetGovernors, sheetSeams, sheetEdges;
  sheetGovernors->SetName(exactmat::arrays::SheetGovernors);
  sheetSeams->SetName(exactmat::arrays::SheetSeams);
  sheetEdges->SetName(exactmat::arrays::SheetConvexEdges);
  for (const exactmat::MAT3DSheet& sheet : mat.sheets)
  {
    sheetGovernors->InsertNextValue(generatorId(sheet.generatorA) + "," + generatorId(sheet.generatorB));
    std::string seams, edges;
    for (int s : sheet.seams)
      seams += (seams.empty() ? "" : " ") + std::to_string(junctions + s);
    for (int e : sheet.convexEdges)
      edges += (edges.empty() ? "" : " ") + labels.edge(e);
    sheetSeams->InsertNextValue(seams);
    sheetEdges->InsertNextValue(edges);
  }
  output->GetFieldData()->AddArray(sheetGovernors);
  output->GetFieldData()->AddArray(sheetSeams);
  output->GetFieldData()->AddArray(sheetEdges);

  exactmat::VerificationOutcome& outcome = result.verification;
  if (this->VerifyOutput)
  {
    t0 = std::chrono::steady_clock::now();
    const exactmat::PatchBoundary exact(boundary);
    const exactmat::MedialVerification v = exactmat::verifyMedialComplex(
      exact, complex, 1, std::max(1e-15, 64.0 * frame.inputRounding()),
      exactmat::smpParallelFor());
    result.measure("VerificationSeconds", secondsSince(t0));
    result.count("NumberOfVerifiedPoints", v.points);
    result.count("NumberOfTouchpointMismatches", v.contactMismatches);
    result.count("NumberOfWitnessedPoints", v.witnessed);
    outcome = exactmat::outcomeOf(v, this->VerificationTolerance, complex, frame);
    // The seam graph's own check (seams per junction), which the points' check cannot see.
    const std::vector<std::string> topology =
      mat.topologyProblems([&frame](const exactmat::Vec3& x) { return frame.toUser(x); });
    if (!topology.empty())
    {
      outcome.passed = false;
      outcome.report += std::string(outcome.report.empty() ? "" : "; ") + std::to_string(topology.size()) +
        " node(s) of the seam graph with the wrong number of seams (first: " + topology.front() + ")";
    }
    result.count("NumberOfTopologyProblems", static_cast<int>(topology.size()));
  }
}

void vtkMAT3DFilter::PublishFigures(const exactmat::PartResult& figures)
{
  this->NumberOfJunctions = static_cast<int>(figures.get("NumberOfJunctions"));
  this->NumberOfSeams = static_cast<int>(figures.get("NumberOfSeams"));
  this->NumberOfSkeletalEdges = static_cast<int>(figures.get("NumberOfSkeletalEdges"));
  this->NumberOfCentreCurves = static_cast<int>(figures.get("NumberOfCentreCurves"));
  this->NumberOfSphereCentres = static_cast<int>(figures.get("NumberOfSphereCentres"));
  this->NumberOfSheets = static_cast<int>(figures.get("NumberOfSheets"));
  this->NumberOfVerifiedPoints = static_cast<int>(figures.get("NumberOfVerifiedPoints"));
  this->NumberOfTouchpointMismatches =
    static_cast<int>(figures.get("NumberOfTouchpointMismatches"));
  this->NumberOfTopologyProblems = static_cast<int>(figures.get("NumberOfTopologyProblems"));
  this->NumberOfWitnessedPoints = static_cast<int>(figures.get("NumberOfWitnessedPoints"));
  this->TracingSeconds = figures.get("TracingSeconds");
  this->VerificationSeconds = figures.get("VerificationSeconds");
}

void vtkMAT3DFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumStep: " << this->MaximumStep << "\n";
  os << indent << "FixedStep: " << this->FixedStep << "\n";
  os << indent << "Step: " << this->Step << "\n";
  os << indent << "JunctionCheckStep: " << this->JunctionCheckStep << "\n";
  os << indent << "NumberOfJunctions: " << this->NumberOfJunctions << "\n";
  os << indent << "NumberOfSeams: " << this->NumberOfSeams << "\n";
  os << indent << "NumberOfSkeletalEdges: " << this->NumberOfSkeletalEdges << "\n";
  os << indent << "NumberOfCentreCurves: " << this->NumberOfCentreCurves << "\n";
  os << indent << "NumberOfSphereCentres: " << this->NumberOfSphereCentres << "\n";
  os << indent << "NumberOfTopologyProblems: " << this->NumberOfTopologyProblems << "\n";
}
