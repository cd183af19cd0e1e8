#include "vtkMAT2DFilter.h"

#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkMATPartResult.h"
#include "vtkMATThreads.h"
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

void vtkMAT2DFilter::ComputePart(vtkUnstructuredGrid* input, vtkPolyData* output,
  exactmat::PartResult& result, const std::function<void(double)>& progress) const
{
  auto t0 = std::chrono::steady_clock::now();
  auto secondsSince = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
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
  result.measure("SetUpSeconds", secondsSince(t0));
  t0 = std::chrono::steady_clock::now();
  exactmat::MAT2DOptions options;
  options.tolerance = this->Tolerance;
  options.fixedStep = this->FixedStep;
  options.step = this->Step;
  options.branchCheckStep = this->BranchCheckStep;
  options.progress = [&progress](double f) { progress(0.9 * f); };
  const exactmat::MedialGraph graph = exactmat::computeMAT2D(generators, options);
  result.measure("TracingSeconds", secondsSince(t0));
  t0 = std::chrono::steady_clock::now();
  GraphWriter(generators, boundary).write(graph, output);
  result.count("NumberOfSegments", static_cast<int>(graph.segments.size()));
  result.count("NumberOfBranchPoints", graph.count(exactmat::MedialPointType::Branch));
  result.count("NumberOfEndPoints",
    graph.count(exactmat::MedialPointType::ConvexVertexEnd) +
      graph.count(exactmat::MedialPointType::CurvatureCentreEnd) +
      graph.count(exactmat::MedialPointType::CircleCentre));
  result.measure("OutputSeconds", secondsSince(t0));
  t0 = std::chrono::steady_clock::now();
  exactmat::VerificationOutcome& outcome = result.verification;
  if (this->VerifyOutput)
  {
    const exactmat::MAT2DVerification v =
      exactmat::verifyMAT2D(generators, graph, exactmat::smpParallelFor());
    outcome.run = true;
    outcome.maximumError = v.maxDistanceError;
    outcome.passed = v.ok(this->VerificationTolerance);
    if (!outcome.passed)
    {
      outcome.report = v.problems(this->VerificationTolerance) + " (largest error at " +
        exactmat::format(boundary.userPoint(v.worstPoint)) + ", Radius " +
        exactmat::format(boundary.userLength(v.worstRadius)) + ")";
    }
  }
  result.measure("VerificationSeconds", secondsSince(t0));
}

void vtkMAT2DFilter::PublishFigures(const exactmat::PartResult& figures)
{
  this->NumberOfSegments = static_cast<int>(figures.get("NumberOfSegments"));
  this->NumberOfBranchPoints = static_cast<int>(figures.get("NumberOfBranchPoints"));
  this->NumberOfEndPoints = static_cast<int>(figures.get("NumberOfEndPoints"));
  this->SetUpSeconds = figures.get("SetUpSeconds");
  this->TracingSeconds = figures.get("TracingSeconds");
  this->OutputSeconds = figures.get("OutputSeconds");
  this->VerificationSeconds = figures.get("VerificationSeconds");
}

void vtkMAT2DFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "FixedStep: " << this->FixedStep << "\n";
  os << indent << "Step: " << this->Step << "\n";
  os << indent << "BranchCheckStep: " << this->BranchCheckStep << "\n";
  os << indent << "NumberOfSegments: " << this->NumberOfSegments << "\n";
  os << indent << "NumberOfBranchPoints: " << this->NumberOfBranchPoints << "\n";
}
