#include "vtkMATAlgorithm.h"

#include "vtkExactMATArrayNames.h"
#include "vtkMATCollection.h"
#include "vtkMATPartResult.h"
#include "vtkMATPartSummary.h"
#include "vtkMATThreads.h"
#include "vtkMATVerificationReport.h"

#include "common/InputError.h"

#include <vtkCompositeDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkCommunicator.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <new>
#include <string>
#include <vector>

vtkMATAlgorithm::vtkMATAlgorithm() = default;
vtkMATAlgorithm::~vtkMATAlgorithm() = default;

int vtkMATAlgorithm::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkMATAlgorithm::FillOutputPortInformation(int, vtkInformation* info)
{
  // vtkPolyData for one boundary, the input's composite type for a collection
  // (RequestDataObject).
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

vtkTypeBool vtkMATAlgorithm::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
    return this->RequestDataObject(request, inInfo, outInfo);
  return this->Superclass::ProcessRequest(request, inInfo, outInfo);
}

int vtkMATAlgorithm::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = vtkDataObject::GetData(outInfo);
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  if (composite)
  {
    if (!output || !output->IsA(composite->GetClassName()))
    {
      vtkSmartPointer<vtkDataObject> made = vtk::TakeSmartPointer(composite->NewInstance());
      outInfo->Set(vtkDataObject::DATA_OBJECT(), made);
    }
  }
  else if (!vtkPolyData::SafeDownCast(output))
  {
    vtkNew<vtkPolyData> made;
    outInfo->Set(vtkDataObject::DATA_OBJECT(), made);
  }
  return 1;
}

namespace
{
using exactmat::PartResult;

double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The message of the exception being handled, as the filter reports it.
std::string currentErrorMessage()
{
  try
  {
    throw;
  }
  catch (const exactmat::InputError& e)
  {
    return e.what();
  }
  catch (const std::bad_alloc&)
  {
    return "out of memory: the input asks for more than this machine can hold";
  }
  catch (const std::exception& e)
  {
    return std::string("internal error: ") + e.what();
  }
  catch (...)
  {
    return "internal error: unknown exception";
  }
}

// Adds the part's figures to its output's field data (one value each).
void attachFigures(vtkDataObject* output, const PartResult& result)
{
  for (const exactmat::PartFigure& f : result.figures)
  {
    vtkSmartPointer<vtkDataArray> a = exactmat::newFigureArray(f);
    a->InsertNextTuple1(f.value);
    output->GetFieldData()->AddArray(a);
  }
}

// One part of a collection: where it is, what it is called, what became of it.
struct Part
{
  vtkDataObject* input = nullptr;
  std::string name;
  exactmat::PartPlace place;
  bool absent = false; // an empty leaf of a distributed collection: another rank's part
  vtkSmartPointer<vtkPolyData> output;
  PartResult result;
  std::string error;
  double seconds = 0.0;

  // PartStatus: 0 verified, 1 not verified, 2 verification failed, 3 failed.
  int status() const
  {
    if (!error.empty())
      return 3;
    if (!result.verification.run)
      return 1;
    return result.verification.passed ? 0 : 2;
  }
};

} // namespace

int vtkMATAlgorithm::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  this->MaximumVerifiedError = 0.0;
  this->VerificationPassed = true;
  this->NumberOfParts = this->NumberOfFailedParts = 0;
  this->PublishFigures(PartResult{});

  vtkMultiProcessController* distributed = exactmat::distributedController(outputVector);
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(input))
  {
    auto* polyData = vtkPolyData::SafeDownCast(output);
    if (distributed)
    {
      // One boundary in a distributed pipeline lives on one rank (a source or reader gives
      // it to piece 0): the others output nothing, unless no rank has it.
      vtkIdType mine = grid->GetNumberOfCells(), total = mine;
      distributed->AllReduce(&mine, &total, 1, vtkCommunicator::SUM_OP);
      if (mine == 0 && total > 0)
        return 1;
    }
    PartResult result;
    std::string error;
    exactmat::withThreads(this->NumberOfThreads, [&]() {
      try
      {
        this->ComputePart(grid, polyData, result, [this](double f) { this->UpdateProgress(f); });
      }
      catch (...)
      {
        error = currentErrorMessage();
      }
    });
    this->NumberOfParts = 1;
    if (!error.empty())
    {
      this->NumberOfFailedParts = 1;
      this->VerificationPassed = false;
      vtkErrorMacro(<< error);
      return 0;
    }
    this->PublishFigures(result);
    attachFigures(polyData, result);
    exactmat::attachVerification(polyData, result.verification);
    this->MaximumVerifiedError = result.verification.maximumError;
    this->VerificationPassed = result.verification.passed;
    if (!result.verification.passed)
    {
      this->NumberOfFailedParts = 1;
      vtkWarningMacro(<< "verification failed: " << result.verification.report);
    }
    this->UpdateProgress(1.0);
    return 1;
  }

  auto* compositeIn = vtkCompositeDataSet::SafeDownCast(input);
  auto* compositeOut = vtkCompositeDataSet::SafeDownCast(output);
  if (!compositeIn || !compositeOut)
  {
    vtkErrorMacro(<< "the input is a " << (input ? input->GetClassName() : "null object")
                  << ": a MAT filter takes a vtkUnstructuredGrid of boundary cells or a "
                     "collection of them");
    return 0;
  }
  compositeOut->CopyStructure(compositeIn);
  std::vector<Part> parts;
  for (const exactmat::CollectionPart& leaf : exactmat::collectionParts(compositeIn))
  {
    Part p;
    p.input = leaf.data;
    p.name = leaf.name;
    p.place = leaf.place;
    p.absent = distributed && exactmat::isEmptyGrid(leaf.data);
    parts.push_back(std::move(p));
  }
  const int n = static_cast<int>(parts.size());

  auto compute = [this](Part& p) {
    const auto t0 = std::chrono::steady_clock::now();
    p.output = vtkSmartPointer<vtkPolyData>::New();
    if (p.absent)
      return;
    try
    {
      auto* grid = vtkUnstructuredGrid::SafeDownCast(p.input);
      if (!grid)
        exactmat::fail(std::string("the part is a ") + p.input->GetClassName() +
          ", not a vtkUnstructuredGrid of boundary cells");
      this->ComputePart(grid, p.output, p.result, [](double) {});
      attachFigures(p.output, p.result);
      exactmat::attachVerification(p.output, p.result.verification);
    }
    catch (...)
    {
      p.error = currentErrorMessage();
      p.output = vtkSmartPointer<vtkPolyData>::New(); // no partial MAT
      p.result = PartResult{};
    }
    p.seconds = secondsSince(t0);
  };
  // Waves of parts, so progress is reported from this thread between them (observers
  // such as ParaView's progress bar must not be called from workers); a wave holds a few
  // parts per thread, so an uneven part costs little idle time.
  const int threads = exactmat::threadsFor(this->NumberOfThreads);
  const int wave = std::max(1, 4 * threads);
  exactmat::withThreads(this->NumberOfThreads, [&]() {
    for (int begin = 0; begin < n; begin += wave)
    {
      const int end = std::min(n, begin + wave);
      vtkSMPTools::For(vtkIdType(begin), vtkIdType(end), vtkIdType(1),
        [&parts, &compute](vtkIdType b, vtkIdType e) {
        for (vtkIdType i = b; i < e; ++i)
          compute(parts[i]);
      });
      this->UpdateProgress(static_cast<double>(end) / std::max(1, n));
      if (this->CheckAbort())
        break;
    }
  });

  std::vector<exactmat::PartRow> rows;
  for (Part& p : parts)
  {
    if (!p.output)
      p.output = vtkSmartPointer<vtkPolyData>::New(); // aborted before this part
    exactmat::PartRow row;
    row.key = p.place.key();
    row.name = p.name;
    row.status = p.absent ? -1 : p.status();
    row.message = p.error.empty() ? p.result.verification.report : p.error;
    row.seconds = p.seconds;
    row.maximumError = p.result.verification.maximumError;
    row.figures = p.result.figures;
    const int status = row.status;
    rows.push_back(std::move(row));
    if (status >= 2) // each rank names the failures among its own parts
      vtkWarningMacro(<< "part '" << p.name << "' "
                      << (status == 3 ? "failed: " + p.error
                                      : "verification failed: " + p.result.verification.report));
  }
  if (distributed)
    rows = exactmat::gatherPartRows(distributed, rows);
  PartResult sums;
  this->NumberOfParts = static_cast<int>(rows.size());
  for (const exactmat::PartRow& row : rows)
  {
    for (const exactmat::PartFigure& f : row.figures)
    {
      auto it = std::find_if(sums.figures.begin(), sums.figures.end(),
        [&f](const exactmat::PartFigure& s) { return s.name == f.name; });
      if (it == sums.figures.end())
        sums.figures.push_back(f);
      else
        it->value += f.value;
    }
    this->MaximumVerifiedError = std::max(this->MaximumVerifiedError, row.maximumError);
    if (row.status >= 2)
    {
      ++this->NumberOfFailedParts;
      this->VerificationPassed = false;
    }
  }
  for (const Part& p : parts)
    exactmat::setPartAt(compositeOut, p.place, p.output);
  this->PublishFigures(sums);
  exactmat::attachPartSummary(compositeOut->GetFieldData(), rows);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMATAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "VerifyOutput: " << this->VerifyOutput << "\n";
  os << indent << "VerificationTolerance: " << this->VerificationTolerance << "\n";
  os << indent << "MaximumVerifiedError: " << this->MaximumVerifiedError << "\n";
  os << indent << "VerificationPassed: " << this->VerificationPassed << "\n";
  os << indent << "NumberOfParts: " << this->NumberOfParts << "\n";
  os << indent << "NumberOfFailedParts: " << this->NumberOfFailedParts << "\n";
}
