#include "vtkMAT2DFilter.h"

#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkMATVerificationReport.h"

#include "brep/NormalisePieces.h"
#include "common/Format.h"
#include "common/InputError.h"
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"

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
#include <exception>
#include <new>
#include <string>

vtkStandardNewMacro(vtkMAT2DFilter);

vtkMAT2DFilter::vtkMAT2DFilter() = default;
vtkMAT2DFilter::~vtkMAT2DFilter() = default;

int vtkMAT2DFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

namespace
{
using namespace exactmat;

// The medial graph as polydata (see the class documentation for the arrays).
class GraphWriter
{
public:
  GraphWriter(const Generators& g, const Boundary2D& boundary)
    : G(g)
    , B(boundary)
  {
    Points->SetDataTypeToDouble();
    Radius->SetName(arrays::Radius);
    Type->SetName(arrays::PointType);
    Foot0->SetName(arrays::Footpoint0);
    Foot0->SetNumberOfComponents(3);
    Foot1->SetName(arrays::Footpoint1);
    Foot1->SetNumberOfComponents(3);
    SegmentId->SetName(arrays::SegmentId);
    Gen0->SetName(arrays::Generator0);
    Gen1->SetName(arrays::Generator1);
    GenList->SetName(arrays::Generators);
  }

  void write(const MedialGraph& graph, vtkPolyData* out)
  {
    for (const MedialNode& n : graph.nodes)
    {
      const vtkIdType id = addPoint(n.sample, static_cast<int>(n.type));
      Verts->InsertNextCell(1, &id);
      SegmentId->InsertNextValue(-1);
      Gen0->InsertNextValue(entity(n.sample.foot[0].g));
      Gen1->InsertNextValue(entity(n.sample.foot[1].g));
      std::string list;
      for (const BoundaryLocation& f : n.footpoints)
        list += (list.empty() ? "" : ",") + name(f.g);
      GenList->InsertNextValue(list);
    }
    for (size_t s = 0; s < graph.segments.size(); ++s)
    {
      const MedialSegment& seg = graph.segments[s];
      std::vector<vtkIdType> ids{ seg.startNode };
      for (size_t i = 1; i + 1 < seg.samples.size(); ++i)
        ids.push_back(addPoint(seg.samples[i], static_cast<int>(MedialPointType::Normal)));
      ids.push_back(seg.endNode);
      Lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      SegmentId->InsertNextValue(static_cast<int>(s));
      Gen0->InsertNextValue(entity(seg.generators[0]));
      Gen1->InsertNextValue(entity(seg.generators[1]));
      GenList->InsertNextValue(name(seg.generators[0]) + "," + name(seg.generators[1]));
    }
    out->SetPoints(Points);
    out->SetVerts(Verts);
    out->SetLines(Lines);
    out->GetPointData()->AddArray(Radius);
    out->GetPointData()->SetScalars(Radius);
    out->GetPointData()->AddArray(Type);
    out->GetPointData()->AddArray(Foot0);
    out->GetPointData()->AddArray(Foot1);
    out->GetCellData()->AddArray(SegmentId);
    out->GetCellData()->AddArray(Gen0);
    out->GetCellData()->AddArray(Gen1);
    out->GetCellData()->AddArray(GenList);
  }

private:
  vtkIdType addPoint(const MedialSample& m, int type)
  {
    const Vec3 x = toUser(m.x);
    const Vec3 f0 = toUser(m.foot[0].point);
    const Vec3 f1 = toUser(m.foot[1].point);
    Radius->InsertNextValue(B.userLength(m.radius));
    Type->InsertNextValue(type);
    Foot0->InsertNextTuple(f0.data());
    Foot1->InsertNextTuple(f1.data());
    return Points->InsertNextPoint(x.data());
  }
  Vec3 toUser(const Vec2& x) const { return B.userPoint(x); }
  int entity(int g) const
  {
    return (g >= 0 && G[g].kind == GeneratorKind::Edge) ? G[g].entity : -1;
  }
  std::string name(int g) const
  {
    if (g < 0)
      return "?";
    return G[g].kind == GeneratorKind::Edge ? std::to_string(G[g].entity)
                                            : "v" + std::to_string(G[g].vertex);
  }

  const Generators& G;
  const Boundary2D& B;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Verts, Lines;
  vtkNew<vtkDoubleArray> Radius, Foot0, Foot1;
  vtkNew<vtkIntArray> Type, SegmentId, Gen0, Gen1;
  vtkNew<vtkStringArray> GenList;
};
} // namespace

int vtkMAT2DFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfSegments = this->NumberOfBranchPoints = this->NumberOfEndPoints = 0;
  this->MaximumVerifiedError = 0.0;
  this->VerificationPassed = true;
  this->TracingSeconds = this->VerificationSeconds = 0.0;
  auto t0 = std::chrono::steady_clock::now();
  auto secondsSince = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  try
  {
    exactmat::checkParameter("Tolerance", this->Tolerance, 1e-12, 1e-1);
    exactmat::checkParameter("Step", this->Step, 1e-9, 1e-1);
    exactmat::checkParameter("BranchCheckStep", this->BranchCheckStep, 1e-9, 1.0);
    exactmat::checkParameter("VerificationTolerance", this->VerificationTolerance, 0.0, 1.0);
    if (exactmat::gridHasSurfaceCells(input))
    {
      exactmat::fail("the input holds surface cells: vtkMAT2DFilter takes the boundary "
                     "curves of a planar domain (use vtkMAT3DFilter for solids)");
    }
    // The whole computation runs in the unit frame; GraphWriter maps back.
    const exactmat::Boundary2D boundary =
      exactmat::buildNormalised(exactmat::curvePiecesFromGrid(input));
    const exactmat::Generators generators(boundary);
    exactmat::MAT2DOptions options;
    options.tolerance = this->Tolerance;
    options.fixedStep = this->FixedStep;
    options.step = this->Step;
    options.branchCheckStep = this->BranchCheckStep;
    options.progress = [this](double f) { this->UpdateProgress(0.9 * f); };
    const exactmat::MedialGraph graph = exactmat::computeMAT2D(generators, options);
    GraphWriter(generators, boundary).write(graph, output);
    this->TracingSeconds = secondsSince(t0);
    t0 = std::chrono::steady_clock::now();
    this->NumberOfSegments = static_cast<int>(graph.segments.size());
    this->NumberOfBranchPoints = graph.count(exactmat::MedialPointType::Branch);
    this->NumberOfEndPoints = graph.count(exactmat::MedialPointType::ConvexVertexEnd) +
      graph.count(exactmat::MedialPointType::CurvatureCentreEnd) +
      graph.count(exactmat::MedialPointType::CircleCentre);
    exactmat::VerificationOutcome outcome;
    if (this->VerifyOutput)
    {
      const exactmat::MAT2DVerification v = exactmat::verifyMAT2D(generators, graph);
      outcome.run = true;
      outcome.maximumError = this->MaximumVerifiedError = v.maxDistanceError;
      outcome.passed = this->VerificationPassed = v.ok(this->VerificationTolerance);
      if (!outcome.passed)
      {
        outcome.report = v.problems(this->VerificationTolerance) + " (largest error at " +
          exactmat::format(boundary.userPoint(v.worstPoint)) + ", Radius " +
          exactmat::format(boundary.userLength(v.worstRadius)) + ")";
        vtkWarningMacro(<< "verification failed: " << outcome.report);
      }
    }
    exactmat::attachVerification(output, outcome);
    this->VerificationSeconds = secondsSince(t0);
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

void vtkMAT2DFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "FixedStep: " << this->FixedStep << "\n";
  os << indent << "Step: " << this->Step << "\n";
  os << indent << "BranchCheckStep: " << this->BranchCheckStep << "\n";
  os << indent << "VerifyOutput: " << this->VerifyOutput << "\n";
  os << indent << "NumberOfSegments: " << this->NumberOfSegments << "\n";
  os << indent << "NumberOfBranchPoints: " << this->NumberOfBranchPoints << "\n";
  os << indent << "VerificationTolerance: " << this->VerificationTolerance << "\n";
  os << indent << "MaximumVerifiedError: " << this->MaximumVerifiedError << "\n";
  os << indent << "VerificationPassed: " << this->VerificationPassed << "\n";
}
