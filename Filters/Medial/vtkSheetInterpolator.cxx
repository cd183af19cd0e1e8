#include "vtkSheetInterpolator.h"

#include "vtkMATBoundaryConversion.h"
#include "vtkMATCollection.h"
#include "vtkMATPartResult.h"
#include "vtkMATPartSummary.h"
#include "vtkMATComplexOutput.h"
#include "vtkMATThreads.h"
#include "vtkMATVerificationReport.h"

#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "mat3d/PatchBoundary.h"
#include "medial/Verification.h"
#include "sheets/CapSheet.h"
#include "sheets/CentreCurveFootprint.h"
#include "sheets/RimSheet.h"
#include "sheets/SheetFit.h"
#include "sheets/SheetCoverage.h"
#include "sheets/SheetInterpolation.h"
#include "sheets/TransitionSheets.h"

#include "vtkExactMATArrayNames.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommunicator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDemandDrivenPipeline.h>
#include <vtkMultiProcessController.h>
#include <vtkSmartPointer.h>
#include <vtkDoubleArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

vtkStandardNewMacro(vtkSheetInterpolator);

vtkSheetInterpolator::vtkSheetInterpolator()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

vtkSheetInterpolator::~vtkSheetInterpolator() = default;

void vtkSheetInterpolator::SetSourceConnection(vtkAlgorithmOutput* algOutput)
{
  this->SetInputConnection(1, algOutput);
}

void vtkSheetInterpolator::SetSourceData(vtkDataObject* source)
{
  this->SetInputData(1, source);
}

int vtkSheetInterpolator::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPolyData" : "vtkUnstructuredGrid");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkSheetInterpolator::FillOutputPortInformation(int, vtkInformation* info)
{
  // Port 0: the MAT with its sheets; port 1: the sheets' B-spline fits as Bézier cells —
  // vtkPolyData and vtkUnstructuredGrid for one solid, the input's composite type for a
  // collection (RequestDataObject).
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

vtkTypeBool vtkSheetInterpolator::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
    return this->RequestDataObject(request, inInfo, outInfo);
  return this->Superclass::ProcessRequest(request, inInfo, outInfo);
}

int vtkSheetInterpolator::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  auto* composite = vtkCompositeDataSet::SafeDownCast(vtkDataObject::GetData(inputVector[0], 0));
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    vtkDataObject* output = vtkDataObject::GetData(info);
    if (composite)
    {
      if (!output || !output->IsA(composite->GetClassName()))
        info->Set(vtkDataObject::DATA_OBJECT(), vtk::TakeSmartPointer(composite->NewInstance()));
    }
    else if (port == 0 && !vtkPolyData::SafeDownCast(output))
      info->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkPolyData>::New());
    else if (port == 1 && !vtkUnstructuredGrid::SafeDownCast(output))
      info->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkUnstructuredGrid>::New());
  }
  return 1;
}

namespace
{
using namespace exactmat;

double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<std::string> words(const std::string& text, char separator)
{
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string word;
  while (std::getline(in, word, separator))
    if (!word.empty())
      out.push_back(word);
  return out;
}

vtkStringArray* fieldStrings(vtkPolyData* data, const char* name)
{
  return vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
}

// vtkMAT3DFilter's output back in the solid's unit frame: points with radius, type,
// contacts and touches; elements in ElementId order with their Governors text.
struct InputComplex
{
  MedialComplex complex;
  std::vector<std::string> governors;
};

InputComplex readComplex(vtkPolyData* mat, const Normalisation& frame)
{
  InputComplex in;
  vtkDataArray* radius = mat->GetPointData()->GetArray(arrays::Radius);
  vtkDataArray* type = mat->GetPointData()->GetArray(arrays::PointType);
  vtkDataArray* contacts = mat->GetPointData()->GetArray(arrays::Touchpoints);
  vtkDataArray* elementId = mat->GetCellData()->GetArray(arrays::ElementId);
  vtkDataArray* elementType = mat->GetCellData()->GetArray(arrays::ElementType);
  auto* governors = vtkStringArray::SafeDownCast(mat->GetCellData()->GetAbstractArray(arrays::Governors));
  if (!radius || !type || !elementId || !elementType)
    fail("input 0 is not a MAT filter's output: it lacks Radius, PointType, ElementId or ElementType");
  const char* footNames[3] = { arrays::Footpoint0, arrays::Footpoint1, arrays::Footpoint2 };
  for (vtkIdType i = 0; i < mat->GetNumberOfPoints(); ++i)
  {
    MedialPoint3D p;
    double x[3];
    mat->GetPoint(i, x);
    p.x = frame.toUnit(Vec3(x[0], x[1], x[2]));
    p.radius = frame.lengthToUnit(radius->GetTuple1(i));
    p.type = static_cast<MedialPoint3DType>(static_cast<int>(type->GetTuple1(i)));
    p.contacts = contacts ? static_cast<int>(contacts->GetTuple1(i)) : 0;
    for (const char* name : footNames)
      if (vtkDataArray* foot = mat->GetPointData()->GetArray(name))
      {
        const double* f = foot->GetTuple3(i);
        const Vec3 t = frame.toUnit(Vec3(f[0], f[1], f[2]));
        if (t.allFinite() && (p.touches.empty() || p.touches.back() != t))
          p.touches.push_back(t);
      }
    in.complex.points.push_back(p);
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mat->GetNumberOfCells(); ++c)
  {
    const int e = static_cast<int>(elementId->GetTuple1(c));
    if (e < 0 || e > 100000000)
      fail("input 0: cell ", c, " has ElementId ", e);
    if (e >= static_cast<int>(in.complex.elements.size()))
    {
      in.complex.elements.resize(e + 1);
      in.governors.resize(e + 1);
    }
    MedialElement& el = in.complex.elements[e];
    el.type = static_cast<MedialElementType>(static_cast<int>(elementType->GetTuple1(c)));
    if (governors)
      in.governors[e] = governors->GetValue(c);
    mat->GetCellPoints(c, ids);
    if (mat->GetCellType(c) == VTK_TRIANGLE && ids->GetNumberOfIds() == 3)
      el.triangles.push_back({ { static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
        static_cast<int>(ids->GetId(2)) } });
    else
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        el.points.push_back(static_cast<int>(ids->GetId(k)));
  }
  return in;
}
// The sheets vtkMAT25DFilter writes (exact: swept profile MAT segments, profile sheets,
// mid-sheets).
bool isSweptSheet(MedialElementType type)
{
  return type == MedialElementType::SweptSheet || type == MedialElementType::ProfileSheet ||
    type == MedialElementType::MidSheet;
}
} // namespace

struct vtkSheetInterpolator::Figures
{
  int sheets = 0, interpolated = 0, failedSheets = 0, triangles = 0, verifiedPoints = 0, mismatches = 0;
  int fitPatches = 0, aboveFit = 0;
  double deviation = 0.0, interpolationSeconds = 0.0, verificationSeconds = 0.0, coverage = 0.0,
         fitError = 0.0, fitSeconds = 0.0, verifiedError = 0.0;
  bool passed = false;
  /// Raised while the solid was filled, emitted by the filter's own thread afterwards
  /// (observers such as ParaView's must not be called from workers).
  std::vector<std::string> warnings;

  /// A collection's sums: counts and times add up, errors and shortfalls take the largest.
  void add(const Figures& o)
  {
    sheets += o.sheets;
    interpolated += o.interpolated;
    failedSheets += o.failedSheets;
    triangles += o.triangles;
    verifiedPoints += o.verifiedPoints;
    mismatches += o.mismatches;
    fitPatches += o.fitPatches;
    aboveFit += o.aboveFit;
    deviation = std::max(deviation, o.deviation);
    coverage = std::max(coverage, o.coverage);
    fitError = std::max(fitError, o.fitError);
    verifiedError = std::max(verifiedError, o.verifiedError);
    interpolationSeconds += o.interpolationSeconds;
    verificationSeconds += o.verificationSeconds;
    fitSeconds += o.fitSeconds;
  }
};

void vtkSheetInterpolator::PublishFigures(const Figures& f)
{
  this->NumberOfSheets = f.sheets;
  this->NumberOfInterpolatedSheets = f.interpolated;
  this->NumberOfFailedSheets = f.failedSheets;
  this->NumberOfTriangles = f.triangles;
  this->NumberOfVerifiedPoints = f.verifiedPoints;
  this->NumberOfTouchpointMismatches = f.mismatches;
  this->NumberOfFitPatches = f.fitPatches;
  this->NumberOfSheetsAboveFitTolerance = f.aboveFit;
  this->MaximumDeviation = f.deviation;
  this->MaximumCoverageShortfall = f.coverage;
  this->MaximumFitError = f.fitError;
  this->MaximumVerifiedError = f.verifiedError;
  this->InterpolationSeconds = f.interpolationSeconds;
  this->VerificationSeconds = f.verificationSeconds;
  this->FitSeconds = f.fitSeconds;
  this->VerificationPassed = f.passed;
}

std::string vtkSheetInterpolator::FillPart(vtkPolyData* mat, vtkUnstructuredGrid* boundary, vtkPolyData* output,
  vtkUnstructuredGrid* fits, Figures& figures, const std::function<void(double)>& progress) const
{
  fits->Initialize();
  std::string error;
  try
  {
    this->Interpolate(mat, boundary, output, fits, figures, progress);
    return error;
  }
  catch (const InputError& e)
  {
    error = e.what();
  }
  catch (const std::bad_alloc&)
  {
    error = "out of memory: the sheets ask for more than this machine can hold";
  }
  catch (const std::exception& e)
  {
    error = std::string("internal error: ") + e.what();
  }
  output->Initialize();
  fits->Initialize();
  return error;
}

int vtkSheetInterpolator::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->PublishFigures(Figures{});
  this->NumberOfParts = this->NumberOfFailedParts = 0;
  vtkDataObject* matObject = vtkDataObject::GetData(inputVector[0]);
  vtkDataObject* boundaryObject = vtkDataObject::GetData(inputVector[1]);
  if (auto* mats = vtkCompositeDataSet::SafeDownCast(matObject))
  {
    auto* boundaries = vtkCompositeDataSet::SafeDownCast(boundaryObject);
    auto* output = vtkCompositeDataSet::SafeDownCast(vtkDataObject::GetData(outputVector, 0));
    auto* fits = vtkCompositeDataSet::SafeDownCast(vtkDataObject::GetData(outputVector, 1));
    if (!boundaries || !output || !fits)
    {
      vtkErrorMacro(<< "input 0 is a collection of MATs: the source must be the collection of solids they "
                       "were computed from (the same structure), not a "
                    << (boundaryObject ? boundaryObject->GetClassName() : "null object"));
      return 0;
    }
    return this->RequestCollection(mats, boundaries, output, fits, outputVector);
  }
  vtkPolyData* mat = vtkPolyData::SafeDownCast(matObject);
  vtkUnstructuredGrid* boundary = vtkUnstructuredGrid::SafeDownCast(boundaryObject);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkUnstructuredGrid* fits = vtkUnstructuredGrid::GetData(outputVector, 1);
  if (!mat || !boundary || !output || !fits)
  {
    vtkErrorMacro(<< "vtkSheetInterpolator needs the MAT (input 0, vtkPolyData) and the exact boundary "
                     "(input 1, the source: vtkUnstructuredGrid), or a collection of each");
    return 0;
  }
  if (vtkMultiProcessController* distributed = distributedController(outputVector))
  {
    // One solid in a distributed pipeline lives on one rank: the others output nothing.
    vtkIdType mine = mat->GetNumberOfPoints(), total = mine;
    distributed->AllReduce(&mine, &total, 1, vtkCommunicator::SUM_OP);
    if (mine == 0 && total > 0)
    {
      fits->Initialize();
      return 1;
    }
  }
  this->NumberOfParts = 1;
  Figures figures;
  const std::string error =
    this->FillPart(mat, boundary, output, fits, figures, [this](double f) { this->UpdateProgress(f); });
  for (const std::string& warning : figures.warnings)
    vtkWarningMacro(<< warning);
  if (!error.empty())
  {
    figures.passed = false;
    this->PublishFigures(figures);
    this->NumberOfFailedParts = 1;
    vtkErrorMacro(<< error);
    return 0;
  }
  this->PublishFigures(figures);
  this->NumberOfFailedParts = this->VerificationPassed ? 0 : 1;
  this->UpdateProgress(1.0);
  return 1;
}

int vtkSheetInterpolator::RequestCollection(vtkCompositeDataSet* mats, vtkCompositeDataSet* boundaries,
  vtkCompositeDataSet* output, vtkCompositeDataSet* fits, vtkInformationVector* outputVector)
{
  vtkMultiProcessController* distributed = distributedController(outputVector);
  output->CopyStructure(mats);
  fits->CopyStructure(mats);
  const std::vector<CollectionPart> parts = collectionParts(mats);
  const int n = static_cast<int>(parts.size());
  std::vector<PartRow> rows(n);
  std::vector<Figures> figures(n);
  std::vector<vtkSmartPointer<vtkPolyData>> partOutputs(n);
  std::vector<vtkSmartPointer<vtkUnstructuredGrid>> partFits(n);
  auto fill = [&](int k) {
    const CollectionPart& part = parts[k];
    const auto t0 = std::chrono::steady_clock::now();
    PartRow& row = rows[k];
    row.key = part.place.key();
    row.name = part.name;
    partOutputs[k] = vtkSmartPointer<vtkPolyData>::New();
    partFits[k] = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto* mat = vtkPolyData::SafeDownCast(part.data);
    auto* boundary = vtkUnstructuredGrid::SafeDownCast(partAt(boundaries, part.place));
    if (mat && mat->GetNumberOfPoints() == 0 && distributed)
      row.status = -1; // another rank's part (or one whose MAT failed on every rank)
    else if (!mat || mat->GetNumberOfPoints() == 0)
    {
      row.status = 3;
      row.message = mat ? "its MAT is empty: the MAT filter failed on this part" : "the part is not a vtkPolyData MAT";
    }
    else if (!boundary || boundary->GetNumberOfCells() == 0)
    {
      row.status = 3;
      row.message = "the source has no solid at this part's place (is it the collection the MATs were computed "
                    "from?)";
    }
    else
    {
      Figures& f = figures[k];
      row.message = this->FillPart(mat, boundary, partOutputs[k], partFits[k], f, [](double) {});
      if (!row.message.empty())
      {
        row.status = 3;
        f = Figures{}; // a failed part adds nothing to the sums
      }
      else
      {
        auto* report =
          vtkStringArray::SafeDownCast(partOutputs[k]->GetFieldData()->GetAbstractArray(arrays::VerificationReport));
        row.message = report && report->GetNumberOfValues() > 0 ? report->GetValue(0) : std::string();
        row.status = !this->VerifyOutput ? 1 : f.passed ? 0 : 2;
        row.maximumError = f.verifiedError;
        PartResult result;
        result.count("NumberOfSheets", f.sheets);
        result.count("NumberOfInterpolatedSheets", f.interpolated);
        result.count("NumberOfFailedSheets", f.failedSheets);
        result.count("NumberOfTriangles", f.triangles);
        result.count("NumberOfFitPatches", f.fitPatches);
        result.count("NumberOfSheetsAboveFitTolerance", f.aboveFit);
        result.measure("MaximumFitError", f.fitError);
        result.measure("MaximumCoverageShortfall", f.coverage);
        result.measure("InterpolationSeconds", f.interpolationSeconds);
        result.measure("VerificationSeconds", f.verificationSeconds);
        row.figures = result.figures;
      }
    }
    row.seconds = secondsSince(t0);
  };
  // The solids are independent: filled concurrently, one solid per thread (each solid's
  // own loops then run on its thread), in waves so that progress and abort are handled
  // on this thread between them. A solid's result does not depend on the threads.
  const int wave = std::max(1, 4 * threadsFor(this->NumberOfThreads));
  int done = 0;
  withThreads(this->NumberOfThreads, [&]() {
    for (int begin = 0; begin < n; begin += wave)
    {
      const int end = std::min(n, begin + wave);
      smpParallelFor()(static_cast<std::size_t>(end - begin), [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i)
          fill(begin + static_cast<int>(i));
      });
      done = end;
      this->UpdateProgress(static_cast<double>(end) / static_cast<double>(n));
      if (this->CheckAbort())
        break;
    }
  });
  rows.resize(done); // parts after an abort are left out, as they always were
  Figures sums;
  for (int k = 0; k < done; ++k)
  {
    for (const std::string& warning : figures[k].warnings)
      vtkWarningMacro(<< "part '" << parts[k].name << "': " << warning);
    if (rows[k].status == 3)
      vtkWarningMacro(<< "part '" << parts[k].name << "' failed: " << rows[k].message);
    sums.add(figures[k]);
    setPartAt(output, parts[k].place, partOutputs[k]);
    setPartAt(fits, parts[k].place, partFits[k]);
  }
  if (distributed)
    rows = gatherPartRows(distributed, rows);
  else
    for (PartRow& row : rows)
      if (row.status < 0)
        row.status = 3;
  sums.passed = true;
  sums.verifiedError = 0.0;
  this->NumberOfParts = static_cast<int>(rows.size());
  for (const PartRow& row : rows)
  {
    sums.verifiedError = std::max(sums.verifiedError, row.maximumError);
    if (row.status >= 2)
    {
      ++this->NumberOfFailedParts;
      sums.passed = false;
    }
  }
  this->PublishFigures(sums);
  attachPartSummary(output->GetFieldData(), rows);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkSheetInterpolator::Interpolate(vtkPolyData* mat, vtkUnstructuredGrid* grid, vtkPolyData* output,
  vtkUnstructuredGrid* fits, Figures& figures, const std::function<void(double)>& progress) const
{
  checkParameter("Tolerance", this->Tolerance, 1e-9, 1e-1);
  checkParameter("MaximumEdgeLength", this->MaximumEdgeLength, 1e-4, 1.0);
  checkParameter("VerificationTolerance", this->VerificationTolerance, 0.0, 1.0);
  checkParameter("FitTolerance", this->FitTolerance, 0.0, 1e-1);
  if (!gridHasSurfaceCells(grid))
    fail("the source holds no surface cells: vtkSheetInterpolator takes the faces of the solid the MAT was "
         "computed from");
  const Boundary3D boundary = buildNormalised(patchPiecesFromGrid(grid));
  const Normalisation& frame = boundary.userFrame();
  InputComplex in = readComplex(mat, frame);
  MedialComplex& complex = in.complex;
  if (!fieldStrings(mat, arrays::SheetGovernors) || !fieldStrings(mat, arrays::SheetSeams))
  {
    bool swept = false;
    for (const MedialElement& e : complex.elements)
      swept = swept || isSweptSheet(e.type);
    if (!swept)
      fail("input 0 is neither vtkMAT3DFilter's output (it lacks the sheets' topology: SheetGovernors, "
           "SheetSeams) nor vtkMAT25DFilter's (it has no swept, profile or mid-sheets)");
    this->PassExactSheets(mat, boundary, in.complex, in.governors, output, figures);
    return;
  }
  const std::vector<Generator3D> generators = medialGenerators(boundary);

  // The sheets' topology: generator pairs by label, seams by ElementId, convex edges by
  // their faces' labels.
  const FaceLabels faceLabels(boundary);
  std::map<std::string, int> generatorByLabel;
  for (int g = 0; g < static_cast<int>(generators.size()); ++g)
    generatorByLabel[faceLabels.generator(generators[g].faces())] = g;
  std::map<std::string, int> edgeByLabel;
  for (int e = 0; e < static_cast<int>(boundary.edges().size()); ++e)
  {
    const Edge3D& edge = boundary.edges()[e];
    edgeByLabel[faceLabels.edge(e)] = e;
    edgeByLabel[faceLabels.face(edge.faceB) + "/" + faceLabels.face(edge.faceA)] = e;
  }
  vtkStringArray* sheetGovernors = fieldStrings(mat, arrays::SheetGovernors);
  vtkStringArray* sheetSeams = fieldStrings(mat, arrays::SheetSeams);
  vtkStringArray* sheetEdges = fieldStrings(mat, arrays::SheetConvexEdges);
  const int tuples = static_cast<int>(sheetGovernors->GetNumberOfValues());
  if (sheetSeams->GetNumberOfValues() != tuples || (sheetEdges && sheetEdges->GetNumberOfValues() != tuples))
    fail("input 0: SheetGovernors, SheetSeams and SheetConvexEdges have different lengths");
  std::vector<std::array<int, 2>> pairs;
  for (int s = 0; s < tuples; ++s)
  {
    const std::vector<std::string> labels = words(sheetGovernors->GetValue(s), ',');
    if (labels.size() != 2 || !generatorByLabel.count(labels[0]) || !generatorByLabel.count(labels[1]))
      fail("sheet ", s, ": its generators \"", sheetGovernors->GetValue(s),
        "\" are not entities of the source (is the source the boundary the MAT was computed from?)");
    pairs.push_back({ { generatorByLabel[labels[0]], generatorByLabel[labels[1]] } });
  }

  auto t0 = std::chrono::steady_clock::now();
  SheetOptions options;
  options.tolerance = this->Tolerance;
  options.maxEdge = this->MaximumEdgeLength;
  const PatchBoundary exact(boundary);
  options.exact = &exact;
  std::vector<SheetGroup> groups = groupSheets(boundary, generators, pairs);
  // The cone sheets at the centre curves' ends (a cylinder's), each built whole: the groups
  // from their convex edges are parts of them.
  std::vector<MedialSheetMesh> caps;
  std::vector<std::string> capErrors;
  for (const CapEnd& end : capEnds(complex, boundary, generators))
  {
    capErrors.emplace_back();
    try
    {
      caps.push_back(interpolateCapSheet(boundary, generators, end, options));
    }
    catch (const InputError& e)
    {
      capErrors.back() = e.what();
      caps.emplace_back();
    }
  }
  dropCapGroups(groups, caps);
  std::map<int, int> sheetOfElement; // ElementId → SheetId
  std::vector<std::string> failures;
  std::vector<MedialSheetMesh> meshes; // for the coverage check
  // Each sheet's border curves and label (checking the input as it goes).
  std::vector<std::vector<SheetBorderCurve>> borders(groups.size());
  std::vector<std::string> labels(groups.size());
  // A sheet is named by its sides' entities, each once ("1,4": a plate's face tiled into
  // 66 patches, and the other face); its tuples name its faces one by one.
  auto entityLabel = [&faceLabels](const std::vector<int>& faces) {
    std::string out;
    for (int f : faces)
      out += (out.empty() ? "" : "/") + faceLabels.entity(f);
    return out;
  };
  auto sideLabel = [&](const SheetGroup& group) {
    std::string out;
    for (const std::vector<int>* side : { &group.a, &group.b })
    {
      out += side == &group.b ? "," : "";
      // (The pieces of one entity — a plate's face tiled into 66 patches — named once.)
      std::vector<std::string> named;
      for (int g : *side)
        if (const std::string l = entityLabel(generators[g].faces());
            std::find(named.begin(), named.end(), l) == named.end())
        {
          out += (named.empty() ? "" : "+") + l;
          named.push_back(l);
        }
    }
    return out;
  };
  for (size_t k = 0; k < groups.size(); ++k)
  {
    const SheetGroup& group = groups[k];
    std::vector<SheetBorderCurve>& curves = borders[k];
    std::set<int> seams;
    for (int s : group.traced)
    {
      for (const std::string& w : words(sheetSeams->GetValue(s), ' '))
      {
        const int e = std::atoi(w.c_str());
        if (e < 0 || e >= static_cast<int>(complex.elements.size()) || complex.elements[e].points.empty())
          fail("sheet ", s, ": its seam ", w, " is not a polyline of input 0");
        seams.insert(e);
      }
      if (sheetEdges)
        for (const std::string& w : words(sheetEdges->GetValue(s), ' '))
          if (!edgeByLabel.count(w))
            fail("sheet ", s, ": its convex edge ", w, " is not an edge of the source");
    }
    for (int e : seams)
    {
      SheetBorderCurve curve;
      for (int id : complex.elements[e].points)
      {
        curve.centres.push_back(complex.points[id].x);
        curve.radii.push_back(complex.points[id].radius);
        curve.ids.push_back(id);
      }
      curves.push_back(std::move(curve));
    }
    labels[k] = sideLabel(group);
  }
  // The sheets are independent: filled in parallel (vtkSMPTools), each into its own slot.
  std::vector<MedialSheetMesh> filled(groups.size());
  std::vector<std::string> errors(groups.size());
  withThreads(this->NumberOfThreads, [&]() {
    smpParallelFor()(groups.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
        try
        {
          filled[k] = interpolateSheet(boundary, generators, groups[k], borders[k], options);
        }
        catch (const InputError& e)
        {
          errors[k] = e.what();
        }
        catch (const std::exception& e)
        {
          errors[k] = std::string("internal error: ") + e.what();
        }
    });
  });
  // A sheet no seam borders was found from its convex edges: two faces meeting at one have
  // a sheet along it, so an empty one is a sheet whose other borders were not found (two
  // fillets across their miter: smooth edges and their spines' end), said as such rather
  // than left to the coverage check alone.
  for (size_t k = 0; k < groups.size(); ++k)
    if (errors[k].empty() && filled[k].triangles.empty() && groups[k].traced.empty())
      errors[k] = "3D MAT sheets: the sheet of " + labels[k] + " has no border but its convex edges (its borders "
        "across smooth edges or at a centre curve's end are not found)";
  // Sheets no seam borders, found beyond the borders of those built (as interpolateSheets
  // does): each new one is a tuple of its own, appended to the sheet arrays.
  addTransitionSheets(boundary, generators, groups, borders, filled, errors, options);
  // A MAT with no seam: each closed rim bounds a sheet of its own (the ellipsoid's), a group
  // of every face it touches on both sides.
  for (const SheetBorderCurve& rim : seamlessRims(complex))
  {
    SheetGroup group;
    errors.emplace_back();
    try
    {
      filled.push_back(interpolateRimSheet(boundary, generators, rim, options));
      group.a = group.b = filled.back().members[0];
    }
    catch (const InputError& e)
    {
      errors.back() = e.what();
      filled.emplace_back();
    }
    if (group.a.empty())
      for (int f = 0; f < static_cast<int>(boundary.faces().size()); ++f)
        group.a.push_back(f);
    group.b = group.a;
    filled.back().members = { { group.a, group.b } };
    groups.push_back(std::move(group));
    borders.push_back({ rim });
  }
  // The cone sheets, a group each (its cap and its canal face).
  for (size_t k = 0; k < caps.size(); ++k)
  {
    SheetGroup group;
    group.a = caps[k].members[0];
    group.b = caps[k].members[1];
    errors.push_back(capErrors[k]);
    if (group.a.empty() || group.b.empty())
    {
      // (Failed: named by the end's faces, which the error message gives.)
      for (int f = 0; f < static_cast<int>(boundary.faces().size()); ++f)
        group.a.push_back(f);
      group.b = group.a;
    }
    filled.push_back(std::move(caps[k]));
    filled.back().members = { { group.a, group.b } };
    groups.push_back(std::move(group));
    borders.emplace_back();
  }
  for (size_t k = labels.size(); k < groups.size(); ++k)
    labels.push_back(sideLabel(groups[k]));
  // Each group's tuples in the sheet arrays: its traced pairs', or a new tuple for a sheet
  // no seam lists (faces meeting at a convex edge), appended to the output's arrays.
  std::vector<std::vector<int>> tupleIds(groups.size());
  std::vector<std::string> extraGovernors, extraEdges;
  for (size_t k = 0; k < groups.size(); ++k)
  {
    tupleIds[k] = groups[k].traced;
    if (tupleIds[k].empty())
    {
      tupleIds[k].push_back(tuples + static_cast<int>(extraGovernors.size()));
      auto label = [&](const std::vector<int>& side) {
        return faceLabels.generator(generators[side.front()].faces());
      };
      extraGovernors.push_back(label(groups[k].a) + "," + label(groups[k].b));
      std::string edges;
      for (int e : convexEdgesBetween(boundary, generators, groups[k]))
        edges += (edges.empty() ? "" : " ") + faceLabels.edge(e);
      extraEdges.push_back(edges);
    }
  }
  const int allTuples = tuples + static_cast<int>(extraGovernors.size());
  // A traced pair in no group has both generators in one plane (groupSheets): no sheet.
  std::vector<int> status(allTuples, 0);
  std::vector<std::string> messages(allTuples, "both generators lie in one plane: no sheet between them");
  for (const std::vector<int>& ids : tupleIds)
    for (int s : ids)
      messages[s].clear();
  progress(0.6);
  // The B-spline fits (port 1), also independent per sheet.
  const auto fitStart = std::chrono::steady_clock::now();
  std::vector<SheetFit> fitted(groups.size());
  std::vector<std::string> fitErrors(groups.size());
  if (this->FitSheets)
  {
    SheetFitOptions fitOptions;
    fitOptions.tolerance = this->FitTolerance > 0.0 ? this->FitTolerance : this->Tolerance;
    withThreads(this->NumberOfThreads, [&]() {
      smpParallelFor()(groups.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k)
          if (errors[k].empty() && !filled[k].triangles.empty())
            try
            {
              fitted[k] = fitSheet(filled[k], boundary.diagonal(), fitOptions);
            }
            catch (const InputError& e)
            {
              fitErrors[k] = e.what();
            }
      });
    });
    this->WriteFits(fitted, fitErrors, labels, tupleIds, allTuples, fitOptions.tolerance, frame, fits, figures);
  }
  figures.fitSeconds = secondsSince(fitStart);
  progress(0.7);
  for (size_t k = 0; k < groups.size(); ++k)
  {
    const std::string& label = labels[k];
    MedialSheetMesh& mesh = filled[k];
    if (!errors[k].empty())
    {
      for (int s : tupleIds[k])
      {
        status[s] = -1;
        messages[s] = errors[k];
      }
      failures.push_back(std::string("sheet ") + label + ": " + errors[k]);
      figures.warnings.push_back("sheet " + label + " not interpolated: " + errors[k]);
      continue;
    }
    if (mesh.triangles.empty())
    {
      for (int s : tupleIds[k])
        status[s] = 0;
      continue;
    }
    ++figures.interpolated;
    for (int s : tupleIds[k])
      status[s] = 1;
    figures.deviation = std::max(figures.deviation, mesh.maxDeviation);
    // Vertices: the seams' own points where the sheet meets them, new points elsewhere.
    std::vector<int> id(mesh.vertices.size());
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
    {
      const SheetVertex& sv = mesh.vertices[v];
      if (sv.source >= 0)
      {
        id[v] = sv.source;
        continue;
      }
      MedialPoint3D p;
      p.x = sv.x;
      p.radius = sv.r;
      p.type = sv.convexEdge ? MedialPoint3DType::ConvexEdge : MedialPoint3DType::Sheet;
      // Two touchpoints inside; on the border (solved on a chord of a seam, or where the
      // pair's sheet goes on as another's) a third may touch too: not counted there.
      p.contacts = sv.border ? 0 : 2;
      if (!sv.convexEdge)
        p.touches = { sv.touch[0], sv.touch[1] };
      else
        p.touches = { sv.x };
      id[v] = static_cast<int>(complex.points.size());
      complex.points.push_back(p);
    }
    MedialElement sheet;
    sheet.type = MedialElementType::Sheet;
    for (const auto& t : mesh.triangles)
      sheet.triangles.push_back({ { id[t[0]], id[t[1]], id[t[2]] } });
    figures.triangles += static_cast<int>(sheet.triangles.size());
    sheetOfElement[static_cast<int>(complex.elements.size())] = tupleIds[k].front();
    complex.elements.push_back(std::move(sheet));
    in.governors.push_back(label);
    meshes.push_back(std::move(mesh));
  }
  figures.sheets = static_cast<int>(groups.size());
  figures.failedSheets = static_cast<int>(failures.size());
  // A convex edge's sample at a vertex is the seam's radius-0 point there.
  complex.weld(1e-12 * boundary.diagonal());
  // A sheet closed along a rim by its own points meets the rim's points only at its ends.
  complex.fanSheetsToCurves();
  figures.interpolationSeconds = secondsSince(t0);

  const MedialComplex& written = complex;
  writeMedialComplex(written, frame,
    [&written, &in](const MedialElement& e) { return in.governors[&e - written.elements.data()]; }, false,
    output);
  vtkDataArray* elementIds = output->GetCellData()->GetArray(arrays::ElementId);
  vtkNew<vtkIntArray> sheetId;
  sheetId->SetName(arrays::SheetId);
  sheetId->SetNumberOfTuples(output->GetNumberOfCells());
  for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
  {
    const auto it = sheetOfElement.find(static_cast<int>(elementIds->GetTuple1(c)));
    sheetId->SetValue(c, it == sheetOfElement.end() ? -1 : it->second);
  }
  output->GetCellData()->AddArray(sheetId);
  output->GetFieldData()->PassData(mat->GetFieldData());
  if (!extraGovernors.empty())
  {
    const char* names[3] = { arrays::SheetGovernors, arrays::SheetSeams, arrays::SheetConvexEdges };
    for (int a = 0; a < 3; ++a)
    {
      vtkNew<vtkStringArray> extended;
      extended->SetName(names[a]);
      if (vtkStringArray* given = fieldStrings(mat, names[a]))
        extended->DeepCopy(given);
      for (size_t k = 0; k < extraGovernors.size(); ++k)
        extended->InsertNextValue(a == 0 ? extraGovernors[k] : a == 1 ? std::string() : extraEdges[k]);
      output->GetFieldData()->AddArray(extended);
    }
  }
  vtkNew<vtkIntArray> statusArray;
  statusArray->SetName(arrays::SheetStatus);
  vtkNew<vtkStringArray> messageArray;
  messageArray->SetName(arrays::SheetMessage);
  for (int s = 0; s < allTuples; ++s)
  {
    statusArray->InsertNextValue(status[s]);
    messageArray->InsertNextValue(messages[s]);
  }
  output->GetFieldData()->AddArray(statusArray);
  output->GetFieldData()->AddArray(messageArray);

  VerificationOutcome outcome = this->VerifyPoints(exact, complex, frame, figures);
  // Completeness: the sheets' footprints cover every face (each boundary point has one
  // maximal ball), whatever the points' own check says.
  figures.coverage = 0.0;
  std::string uncovered;
  int uncoveredFaces = 0;
  // (What centre curves' circles cover counts, and a ball's centre covers its whole sphere.)
  std::vector<double> footprints = centreCurveFootprints(boundary, generators, centreCurveTouches(complex));
  const std::vector<double> ball = sphericalFaceFootprints(boundary, complex, 1e-9 * boundary.diagonal());
  footprints.resize(ball.size(), 0.0);
  for (size_t f = 0; f < ball.size(); ++f)
    footprints[f] += ball[f];
  for (const FaceCoverage& c : sheetCoverage(boundary, meshes, footprints))
  {
    figures.coverage = std::max(figures.coverage, c.shortfall());
    if (c.shortfall() > 10.0 * this->Tolerance + 1e-9 && ++uncoveredFaces == 1)
    {
      std::ostringstream line;
      line << "face " << faceLabels.face(c.face) << ": its sheets touch " << 100.0 * c.covered / c.area
           << " % of it";
      uncovered = line.str();
    }
  }
  if (uncoveredFaces > 0)
  {
    outcome.passed = false;
    outcome.report += std::string(outcome.report.empty() ? "" : "; ") + std::to_string(uncoveredFaces) +
      " face(s) not covered by the sheets' touchpoints, a sheet is incomplete (first: " + uncovered + ")";
  }
  if (!failures.empty())
  {
    outcome.passed = false;
    outcome.report += std::string(outcome.report.empty() ? "" : "; ") + std::to_string(failures.size()) +
      " sheet(s) not interpolated (first: " + failures.front() + ")";
  }
  attachVerification(output, outcome);
  figures.passed = outcome.passed;
  figures.verifiedError = outcome.maximumError;
  if (!outcome.passed)
    figures.warnings.push_back("verification failed: " + outcome.report);
}

void vtkSheetInterpolator::WriteFits(const std::vector<SheetFit>& fitted, const std::vector<std::string>& fitErrors,
  const std::vector<std::string>& labels, const std::vector<std::vector<int>>& tupleIds, int tuples,
  double tolerance, const Normalisation& frame, vtkUnstructuredGrid* fits, Figures& figures) const
{
  BoundaryGridBuilder builder;
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(arrays::Radius);
  vtkNew<vtkIntArray> sheetId;
  sheetId->SetName(arrays::SheetId);
  vtkNew<vtkDoubleArray> cellError;
  cellError->SetName(arrays::SheetFitError);
  vtkNew<vtkDoubleArray> tupleError;
  tupleError->SetName(arrays::SheetFitError);
  tupleError->SetNumberOfTuples(tuples);
  tupleError->Fill(-1.0);
  vtkNew<vtkDoubleArray> trimLoops;
  trimLoops->SetName(arrays::SheetTrimLoops);
  trimLoops->SetNumberOfComponents(2);
  vtkNew<vtkIntArray> trimOffsets;
  trimOffsets->SetName(arrays::SheetTrimLoopOffsets);
  vtkNew<vtkIntArray> trimSheet;
  trimSheet->SetName(arrays::SheetTrimLoopSheet);
  for (size_t k = 0; k < fitted.size(); ++k)
  {
    if (!fitErrors[k].empty())
    {
      ++figures.aboveFit;
      figures.warnings.push_back("sheet " + labels[k] + " not fitted: " + fitErrors[k]);
      continue;
    }
    const SheetFit& fit = fitted[k];
    if (fit.patches.empty())
      continue;
    figures.fitError = std::max(figures.fitError, fit.maxError());
    if (!fit.withinTolerance)
    {
      ++figures.aboveFit;
      std::ostringstream warning;
      warning << "the B-spline fit of sheet " << labels[k] << " is off by " << fit.maxError()
              << " of the size (FitTolerance " << tolerance << ") with " << fit.countS << " x " << fit.countT
              << " control points";
      figures.warnings.push_back(warning.str());
    }
    for (int s : tupleIds[k])
      tupleError->SetValue(s, fit.maxError());
    for (const std::vector<Vec2>& loop : fit.trimLoops)
    {
      trimOffsets->InsertNextValue(static_cast<int>(trimLoops->GetNumberOfTuples()));
      trimSheet->InsertNextValue(tupleIds[k].front());
      for (const Vec2& st : loop)
        trimLoops->InsertNextTuple2(st.x(), st.y());
    }
    for (const SheetFitPatch& patch : fit.patches)
    {
      // The fit lives in the unit frame; the frame is affine, so mapping the control
      // points maps the surface exactly.
      Vec4List net;
      for (const Vec4& h : patch.centre.homogeneousNet())
      {
        const Vec3 x = frame.toUser(h.head<3>());
        net.emplace_back(x.x(), x.y(), x.z(), 1.0);
      }
      builder.addPatch(BezierPatch(patch.centre.degreeU(), patch.centre.degreeV(), net), tupleIds[k].front(),
        patch.s0, patch.s1, patch.t0, patch.t1);
      // (addPatch appends the net's points in its order, as the radius coefficients are.)
      for (double r : patch.radius)
        radius->InsertNextValue(frame.lengthToUser(r));
      sheetId->InsertNextValue(tupleIds[k].front());
      cellError->InsertNextValue(fit.maxError());
      ++figures.fitPatches;
    }
  }
  fits->ShallowCopy(builder.grid());
  if (fits->GetNumberOfPoints() != radius->GetNumberOfTuples())
    fail("internal error: the fitted patches have ", fits->GetNumberOfPoints(), " control points but ",
      radius->GetNumberOfTuples(), " radius coefficients");
  fits->GetPointData()->AddArray(radius);
  fits->GetPointData()->SetActiveScalars(arrays::Radius);
  // The builder's entity array is the sheet here: named as the sheets are.
  fits->GetCellData()->RemoveArray(arrays::FaceId);
  fits->GetCellData()->AddArray(sheetId);
  fits->GetCellData()->AddArray(cellError);
  fits->GetFieldData()->AddArray(tupleError);
  trimOffsets->InsertNextValue(static_cast<int>(trimLoops->GetNumberOfTuples()));
  fits->GetFieldData()->AddArray(trimLoops);
  fits->GetFieldData()->AddArray(trimOffsets);
  fits->GetFieldData()->AddArray(trimSheet);
}

VerificationOutcome vtkSheetInterpolator::VerifyPoints(
  const PatchBoundary& exact, const MedialComplex& complex, const Normalisation& frame, Figures& figures) const
{
  VerificationOutcome outcome;
  if (!this->VerifyOutput)
    return outcome;
  const auto t0 = std::chrono::steady_clock::now();
  int stride = 1;
  if (this->MaximumSheetPointsVerified > 0)
  {
    const int sheetPoints = complex.countPoints(MedialPoint3DType::Sheet);
    stride = std::max(1, (sheetPoints + this->MaximumSheetPointsVerified - 1) / this->MaximumSheetPointsVerified);
  }
  MedialVerification v;
  withThreads(this->NumberOfThreads, [&]() {
    v = verifyMedialComplex(exact, complex, stride, std::max(1e-15, 64.0 * frame.inputRounding()), smpParallelFor());
  });
  figures.verificationSeconds = secondsSince(t0);
  figures.verifiedPoints = v.points;
  figures.mismatches = v.contactMismatches;
  return outcomeOf(v, this->VerificationTolerance, complex, frame);
}

// vtkMAT25DFilter's sheets are exact already (the profile's MAT points swept exactly):
// they pass through, each sheet element numbered as a sheet, and its points are checked
// against the source like the interpolated ones.
void vtkSheetInterpolator::PassExactSheets(vtkPolyData* mat, const Boundary3D& boundary,
  const MedialComplex& complex, const std::vector<std::string>& governors, vtkPolyData* output,
  Figures& figures) const
{
  output->ShallowCopy(mat);
  std::map<int, int> sheetOfElement;
  vtkNew<vtkStringArray> sheetGovernors;
  sheetGovernors->SetName(arrays::SheetGovernors);
  vtkNew<vtkIntArray> statusArray;
  statusArray->SetName(arrays::SheetStatus);
  vtkNew<vtkStringArray> messageArray;
  messageArray->SetName(arrays::SheetMessage);
  for (int e = 0; e < static_cast<int>(complex.elements.size()); ++e)
    if (isSweptSheet(complex.elements[e].type) && !complex.elements[e].triangles.empty())
    {
      sheetOfElement[e] = static_cast<int>(sheetOfElement.size());
      sheetGovernors->InsertNextValue(e < static_cast<int>(governors.size()) ? governors[e] : std::string());
      statusArray->InsertNextValue(1);
      messageArray->InsertNextValue(std::string("exact ") + toString(complex.elements[e].type) +
        " from vtkMAT25DFilter (passed through)");
      figures.triangles += static_cast<int>(complex.elements[e].triangles.size());
    }
  figures.sheets = figures.interpolated = static_cast<int>(sheetOfElement.size());
  vtkDataArray* elementIds = mat->GetCellData()->GetArray(arrays::ElementId);
  vtkNew<vtkIntArray> sheetId;
  sheetId->SetName(arrays::SheetId);
  sheetId->SetNumberOfTuples(output->GetNumberOfCells());
  for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
  {
    const auto it = sheetOfElement.find(static_cast<int>(elementIds->GetTuple1(c)));
    sheetId->SetValue(c, it == sheetOfElement.end() ? -1 : it->second);
  }
  output->GetCellData()->AddArray(sheetId);
  output->GetFieldData()->AddArray(sheetGovernors);
  output->GetFieldData()->AddArray(statusArray);
  output->GetFieldData()->AddArray(messageArray);
  const PatchBoundary exact(boundary);
  const VerificationOutcome outcome = this->VerifyPoints(exact, complex, boundary.userFrame(), figures);
  // (Coverage needs each sheet point's touchpoints, which vtkMAT25DFilter does not write:
  // not measured here; its sheets cover the solid by construction.)
  figures.coverage = 0.0;
  attachVerification(output, outcome);
  figures.passed = outcome.passed;
  figures.verifiedError = outcome.maximumError;
  if (!outcome.passed)
    figures.warnings.push_back("verification failed: " + outcome.report);
}

void vtkSheetInterpolator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumEdgeLength: " << this->MaximumEdgeLength << "\n";
  os << indent << "VerifyOutput: " << this->VerifyOutput << "\n";
  os << indent << "VerificationTolerance: " << this->VerificationTolerance << "\n";
  os << indent << "MaximumSheetPointsVerified: " << this->MaximumSheetPointsVerified << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "NumberOfSheets: " << this->NumberOfSheets << "\n";
  os << indent << "NumberOfFailedSheets: " << this->NumberOfFailedSheets << "\n";
  os << indent << "FitSheets: " << this->FitSheets << "\n";
  os << indent << "FitTolerance: " << this->FitTolerance << "\n";
  os << indent << "NumberOfFitPatches: " << this->NumberOfFitPatches << "\n";
  os << indent << "MaximumFitError: " << this->MaximumFitError << "\n";
}
