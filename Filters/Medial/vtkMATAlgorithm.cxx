#include "vtkMATAlgorithm.h"

#include "vtkExactMATArrayNames.h"
#include "vtkMATPartResult.h"
#include "vtkMATThreads.h"
#include "vtkMATVerificationReport.h"

#include "common/InputError.h"

#include <vtkCompositeDataSet.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPartitionedDataSetCollection.h>
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
    vtkSmartPointer<vtkDataArray> a;
    if (f.integer)
      a = vtkSmartPointer<vtkIntArray>::New();
    else
      a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(f.name.c_str());
    a->InsertNextTuple1(f.value);
    output->GetFieldData()->AddArray(a);
  }
}

// One part of a collection: where it is, what it is called, what became of it.
struct Part
{
  vtkDataObject* input = nullptr;
  std::string name;
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

// Visits the leaves of a collection in input order: visit(leaf, name, place), where
// place(o) puts o at the leaf's position in `out` (which has the input's structure).
void visitParts(vtkCompositeDataSet* in, vtkCompositeDataSet* out,
  const std::function<void(vtkDataObject*, const std::string&,
    const std::function<void(vtkDataObject*)>&)>& visit)
{
  auto* pdcIn = vtkPartitionedDataSetCollection::SafeDownCast(in);
  auto* pdcOut = vtkPartitionedDataSetCollection::SafeDownCast(out);
  if (pdcIn && pdcOut)
  {
    for (unsigned int i = 0; i < pdcIn->GetNumberOfPartitionedDataSets(); ++i)
    {
      vtkPartitionedDataSet* pds = pdcIn->GetPartitionedDataSet(i);
      if (!pds)
        continue;
      std::string name = "part " + std::to_string(i);
      if (pdcIn->HasMetaData(i) && pdcIn->GetMetaData(i)->Has(vtkCompositeDataSet::NAME()))
        name = pdcIn->GetMetaData(i)->Get(vtkCompositeDataSet::NAME());
      const unsigned int n = pds->GetNumberOfPartitions();
      for (unsigned int j = 0; j < n; ++j)
        if (vtkDataObject* leaf = pds->GetPartitionAsDataObject(j))
          visit(leaf, n > 1 ? name + " #" + std::to_string(j) : name,
            [pdcOut, i, j](vtkDataObject* o) { pdcOut->SetPartition(i, j, o); });
    }
    return;
  }
  vtkSmartPointer<vtkCompositeDataIterator> it = vtk::TakeSmartPointer(in->NewIterator());
  if (auto* tree = vtkDataObjectTreeIterator::SafeDownCast(it))
  {
    tree->VisitOnlyLeavesOn();
    tree->TraverseSubTreeOn();
  }
  it->SkipEmptyNodesOn();
  int k = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem(), ++k)
  {
    std::string name = "part " + std::to_string(k);
    if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
      name = it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
    visit(it->GetCurrentDataObject(), name,
      [out, &it](vtkDataObject* o) { out->SetDataSet(it, o); });
  }
}

// The collection's summary: one row per part (see the class documentation).
void attachSummary(vtkDataObject* output, const std::vector<Part>& parts)
{
  vtkNew<vtkStringArray> names, messages;
  vtkNew<vtkIntArray> status;
  vtkNew<vtkDoubleArray> seconds, errors;
  names->SetName(exactmat::arrays::PartName);
  messages->SetName(exactmat::arrays::PartMessage);
  status->SetName(exactmat::arrays::PartStatus);
  seconds->SetName(exactmat::arrays::PartSeconds);
  errors->SetName(exactmat::arrays::MaximumVerifiedError);
  // Every figure any part has, in the order the parts first name them.
  std::vector<exactmat::PartFigure> columns;
  for (const Part& p : parts)
    for (const exactmat::PartFigure& f : p.result.figures)
      if (std::none_of(columns.begin(), columns.end(),
            [&f](const exactmat::PartFigure& c) { return c.name == f.name; }))
        columns.push_back(f);
  std::vector<vtkSmartPointer<vtkDataArray>> figureArrays;
  for (const exactmat::PartFigure& c : columns)
  {
    vtkSmartPointer<vtkDataArray> a;
    if (c.integer)
      a = vtkSmartPointer<vtkIntArray>::New();
    else
      a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(c.name.c_str());
    figureArrays.push_back(a);
  }
  for (const Part& p : parts)
  {
    names->InsertNextValue(p.name);
    status->InsertNextValue(p.status());
    messages->InsertNextValue(p.error.empty() ? p.result.verification.report : p.error);
    seconds->InsertNextValue(p.seconds);
    errors->InsertNextValue(p.result.verification.maximumError);
    for (size_t c = 0; c < columns.size(); ++c)
      figureArrays[c]->InsertNextTuple1(p.result.get(columns[c].name));
  }
  vtkFieldData* fd = output->GetFieldData();
  fd->AddArray(names);
  fd->AddArray(status);
  fd->AddArray(messages);
  fd->AddArray(seconds);
  fd->AddArray(errors);
  for (auto& a : figureArrays)
    fd->AddArray(a);
}
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

  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(input))
  {
    auto* polyData = vtkPolyData::SafeDownCast(output);
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
  visitParts(compositeIn, compositeOut,
    [&parts](vtkDataObject* leaf, const std::string& name, const std::function<void(vtkDataObject*)>&) {
      Part p;
      p.input = leaf;
      p.name = name;
      parts.push_back(std::move(p));
    });
  const int n = static_cast<int>(parts.size());
  this->NumberOfParts = n;

  auto compute = [this](Part& p) {
    const auto t0 = std::chrono::steady_clock::now();
    p.output = vtkSmartPointer<vtkPolyData>::New();
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

  PartResult sums;
  for (Part& p : parts)
  {
    if (!p.output)
      p.output = vtkSmartPointer<vtkPolyData>::New(); // aborted before this part
    for (const exactmat::PartFigure& f : p.result.figures)
    {
      auto it = std::find_if(sums.figures.begin(), sums.figures.end(),
        [&f](const exactmat::PartFigure& s) { return s.name == f.name; });
      if (it == sums.figures.end())
        sums.figures.push_back(f);
      else
        it->value += f.value;
    }
    this->MaximumVerifiedError =
      std::max(this->MaximumVerifiedError, p.result.verification.maximumError);
    const int status = p.status();
    if (status >= 2)
    {
      ++this->NumberOfFailedParts;
      this->VerificationPassed = false;
      vtkWarningMacro(<< "part '" << p.name << "' "
                      << (status == 3 ? "failed: " + p.error
                                      : "verification failed: " + p.result.verification.report));
    }
  }
  size_t k = 0;
  visitParts(compositeIn, compositeOut,
    [&parts, &k](vtkDataObject*, const std::string&, const std::function<void(vtkDataObject*)>& place) {
      if (k < parts.size())
        place(parts[k++].output);
    });
  this->PublishFigures(sums);
  attachSummary(compositeOut, parts);
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
