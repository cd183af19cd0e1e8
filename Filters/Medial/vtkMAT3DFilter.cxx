#include "vtkMAT3DFilter.h"

#include "vtkMATBoundaryConversion.h"
#include "vtkMATComplexOutput.h"
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

int vtkMAT3DFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

namespace
{
double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
} // namespace

int vtkMAT3DFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfJunctions = this->NumberOfSeams = this->NumberOfSheets = this->NumberOfVerifiedPoints = 0;
  this->NumberOfSkeletalEdges = 0;
  this->NumberOfTopologyProblems = 0;
  this->NumberOfTouchpointMismatches = 0;
  this->MaximumVerifiedError = this->TracingSeconds = this->VerificationSeconds = 0.0;
  this->VerificationPassed = true;
  try
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
    options.progress = [this](double f) { this->UpdateProgress(0.8 * f); };
    const exactmat::MAT3D mat = exactmat::computeMAT3D(boundary, options);
    this->TracingSeconds = secondsSince(t0);
    const exactmat::MedialComplex complex = mat.complex();
    auto faceId = [&boundary](int f) {
      const exactmat::Face3D& face = boundary.faces()[f];
      return std::to_string(face.entity >= 0 ? face.entity : face.piece);
    };
    // A generator as the user's face ids: a face's id; a reflex edge's or corner's faces
    // joined by "/".
    auto generatorId = [&mat, &faceId](int g) {
      std::string out;
      for (int f : mat.generators[g].faces)
        out += (out.empty() ? "" : "/") + faceId(f);
      return out;
    };
    auto generatorIds = [&generatorId](const exactmat::MedialElement& e) {
      std::string out;
      for (int g : e.governors)
        out += (out.empty() ? "" : ",") + generatorId(g);
      return out;
    };
    exactmat::writeMedialComplex(complex, frame, generatorIds, false, output);
    this->NumberOfJunctions = mat.junctionCount();
    this->NumberOfSeams = static_cast<int>(mat.seams.size());
    this->NumberOfSkeletalEdges = static_cast<int>(mat.skeletalEdges.size());
    this->NumberOfSheets = static_cast<int>(mat.sheets.size());
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
        seams += (seams.empty() ? "" : " ") + std::to_string(this->NumberOfJunctions + s);
      for (int e : sheet.convexEdges)
        edges += (edges.empty() ? "" : " ") + faceId(boundary.edges()[e].faceA) + "/" +
          faceId(boundary.edges()[e].faceB);
      sheetSeams->InsertNextValue(seams);
      sheetEdges->InsertNextValue(edges);
    }
    output->GetFieldData()->AddArray(sheetGovernors);
    output->GetFieldData()->AddArray(sheetSeams);
    output->GetFieldData()->AddArray(sheetEdges);

    exactmat::VerificationOutcome outcome;
    if (this->VerifyOutput)
    {
      t0 = std::chrono::steady_clock::now();
      const exactmat::PatchBoundary exact(boundary);
      const exactmat::MedialVerification v = exactmat::verifyMedialComplex(
        exact, complex, 1, std::max(1e-15, 64.0 * frame.inputRounding()));
      this->VerificationSeconds = secondsSince(t0);
      this->NumberOfVerifiedPoints = v.points;
      this->MaximumVerifiedError = v.maxDistanceError;
      this->NumberOfTouchpointMismatches = v.contactMismatches;
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
      this->NumberOfTopologyProblems = static_cast<int>(topology.size());
      this->VerificationPassed = outcome.passed;
      if (!outcome.passed)
        vtkWarningMacro(<< "verification failed: " << outcome.report);
    }
    exactmat::attachVerification(output, outcome);
    this->UpdateProgress(1.0);
  }
  catch (const exactmat::InputError& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "out of memory: the input asks for more than this machine can hold");
    return 0;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "internal error: " << e.what());
    return 0;
  }
  return 1;
}

void vtkMAT3DFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumStep: " << this->MaximumStep << "\n";
  os << indent << "FixedStep: " << this->FixedStep << "\n";
  os << indent << "Step: " << this->Step << "\n";
  os << indent << "JunctionCheckStep: " << this->JunctionCheckStep << "\n";
  os << indent << "VerifyOutput: " << this->VerifyOutput << "\n";
  os << indent << "VerificationTolerance: " << this->VerificationTolerance << "\n";
  os << indent << "NumberOfJunctions: " << this->NumberOfJunctions << "\n";
  os << indent << "NumberOfSeams: " << this->NumberOfSeams << "\n";
  os << indent << "NumberOfSkeletalEdges: " << this->NumberOfSkeletalEdges << "\n";
  os << indent << "NumberOfTopologyProblems: " << this->NumberOfTopologyProblems << "\n";
  os << indent << "MaximumVerifiedError: " << this->MaximumVerifiedError << "\n";
  os << indent << "VerificationPassed: " << this->VerificationPassed << "\n";
}
