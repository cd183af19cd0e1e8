// Collections of parts through the MAT filters (composite input, one part per partition),
// and threads: every part's MAT identical to its own run, a bad part reported by name
// without stopping the others, threaded verification identical to sequential.
#include "vtkExactMATArrayNames.h"
#include "vtkMAT25DFilter.h"
#include "vtkMAT2DFilter.h"
#include "vtkMAT3DFilter.h"
#include "vtkNURBSSource.h"
#include "vtkSheetInterpolator.h"

#include "TestHelpers.h"
#include "vtkMATThreads.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPartitionedDataSetCollection.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace exactmat;

namespace
{
struct NamedPart
{
  std::string name;
  vtkSmartPointer<vtkUnstructuredGrid> boundary;
};

// 22 good planar domains: every 2D catalogue shape at two sizes.
std::vector<NamedPart> catalogueParts()
{
  std::vector<NamedPart> parts;
  for (const char* name : { "rectangle", "rounded-rectangle", "circle", "ellipse", "annulus",
         "l-shape", "star", "blob", "spiral", "plate-with-holes", "narrow-passage" })
    for (int variant = 0; variant < 2; ++variant)
    {
      vtkNew<vtkNURBSSource> source;
      source->SetShapeName(name);
      source->SetWidth(variant == 0 ? 4.0 : 5.5);
      source->Update();
      parts.push_back({ std::string(name) + "-" + std::to_string(variant),
        vtkSmartPointer<vtkUnstructuredGrid>(source->GetOutput()) });
    }
  return parts;
}

// Not a domain: one straight line, an open loop.
vtkSmartPointer<vtkUnstructuredGrid> openLoop()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  grid->SetPoints(points);
  const vtkIdType ids[2] = { 0, 1 };
  grid->InsertNextCell(VTK_LINE, 2, ids);
  return grid;
}

// Bit-for-bit equality of two MAT outputs: points, cells and every point data array.
void expectIdentical(vtkPolyData* a, vtkPolyData* b, const std::string& what)
{
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints()) << what;
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells()) << what;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double x[3], y[3];
    a->GetPoint(i, x);
    b->GetPoint(i, y);
    ASSERT_TRUE(x[0] == y[0] && x[1] == y[1] && x[2] == y[2]) << what << " point " << i;
  }
  for (int k = 0; k < a->GetPointData()->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* u = a->GetPointData()->GetArray(k);
    if (!u)
      continue;
    vtkDataArray* v = b->GetPointData()->GetArray(u->GetName());
    ASSERT_NE(v, nullptr) << what << " " << u->GetName();
    for (vtkIdType i = 0; i < u->GetNumberOfValues(); ++i)
      ASSERT_EQ(u->GetVariantValue(i), v->GetVariantValue(i)) << what << " " << u->GetName();
  }
}

// The catalogue's solids as a collection, one named part each.
vtkSmartPointer<vtkPartitionedDataSetCollection> catalogueSolids(const std::vector<std::string>& names)
{
  auto collection = vtkSmartPointer<vtkPartitionedDataSetCollection>::New();
  for (unsigned int i = 0; i < names.size(); ++i)
  {
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(names[i].c_str());
    source->Update();
    collection->SetPartition(i, 0, source->GetOutput());
    collection->GetMetaData(i)->Set(vtkCompositeDataSet::NAME(), names[i].c_str());
  }
  return collection;
}

int intField(vtkDataObject* o, const char* name, vtkIdType i = 0)
{
  auto* a = vtkIntArray::SafeDownCast(o->GetFieldData()->GetAbstractArray(name));
  return a ? a->GetValue(i) : -100;
}
std::string stringField(vtkDataObject* o, const char* name, vtkIdType i)
{
  auto* a = vtkStringArray::SafeDownCast(o->GetFieldData()->GetAbstractArray(name));
  return a ? a->GetValue(i) : std::string("<no array>");
}
} // namespace

TEST(MATCollections, PartitionedCollectionGivesEachPartsMATAndNamesTheBadPart)
{
  std::vector<NamedPart> parts = catalogueParts();
  parts.insert(parts.begin() + 7, { "broken-sketch", openLoop() });
  vtkNew<vtkPartitionedDataSetCollection> collection;
  for (unsigned int i = 0; i < parts.size(); ++i)
  {
    collection->SetPartition(i, 0, parts[i].boundary);
    collection->GetMetaData(i)->Set(vtkCompositeDataSet::NAME(), parts[i].name.c_str());
  }
  vtkNew<vtkMAT2DFilter> all;
  all->SetInputDataObject(collection);
  all->SetNumberOfThreads(2);
  all->Update();
  auto* out = vtkPartitionedDataSetCollection::SafeDownCast(all->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(out->GetNumberOfPartitionedDataSets(), parts.size());
  EXPECT_EQ(all->GetNumberOfParts(), static_cast<int>(parts.size()));
  EXPECT_EQ(all->GetNumberOfFailedParts(), 1);
  EXPECT_FALSE(all->GetVerificationPassed());
  EXPECT_LE(all->GetMaximumVerifiedError(), 1e-9);

  int segments = 0;
  for (unsigned int i = 0; i < parts.size(); ++i)
  {
    EXPECT_EQ(stringField(out, arrays::PartName, i), parts[i].name);
    auto* mat = vtkPolyData::SafeDownCast(out->GetPartition(i, 0));
    ASSERT_NE(mat, nullptr) << parts[i].name;
    if (parts[i].name == "broken-sketch")
    {
      EXPECT_EQ(intField(out, arrays::PartStatus, i), 3);
      EXPECT_NE(stringField(out, arrays::PartMessage, i).find("open"), std::string::npos)
        << stringField(out, arrays::PartMessage, i);
      EXPECT_EQ(mat->GetNumberOfPoints(), 0);
      continue;
    }
    EXPECT_EQ(intField(out, arrays::PartStatus, i), 0) << parts[i].name << ": "
                                                       << stringField(out, arrays::PartMessage, i);
    // The same part alone, on one thread: the same MAT, bit for bit, and the same figures.
    vtkNew<vtkMAT2DFilter> one;
    one->SetInputData(parts[i].boundary);
    one->SetNumberOfThreads(1);
    one->Update();
    expectIdentical(one->GetOutput(), mat, parts[i].name);
    EXPECT_EQ(intField(mat, "NumberOfSegments"), one->GetNumberOfSegments()) << parts[i].name;
    EXPECT_EQ(intField(mat, arrays::VerificationStatus), 1) << parts[i].name;
    EXPECT_EQ(intField(out, "NumberOfBranchPoints", i), one->GetNumberOfBranchPoints());
    segments += one->GetNumberOfSegments();
  }
  EXPECT_EQ(all->GetNumberOfSegments(), segments);
}

TEST(MATCollections, MultiBlockOfProfilesThroughTheSweptFilter)
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  const std::vector<std::string> names = { "rectangle", "l-shape", "star", "plate-with-holes" };
  for (unsigned int i = 0; i < names.size(); ++i)
  {
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(names[i].c_str());
    source->Update();
    blocks->SetBlock(i, source->GetOutput());
    blocks->GetMetaData(i)->Set(vtkCompositeDataSet::NAME(), names[i].c_str());
  }
  // A nested block: parts are the leaves, wherever they are.
  vtkNew<vtkMultiBlockDataSet> nested;
  nested->SetBlock(0, openLoop());
  nested->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "open");
  blocks->SetBlock(static_cast<unsigned int>(names.size()), nested);

  vtkNew<vtkMAT25DFilter> all;
  all->SetInputDataObject(blocks);
  all->SetLength(2.0);
  all->Update();
  auto* out = vtkMultiBlockDataSet::SafeDownCast(all->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(all->GetNumberOfParts(), 5);
  EXPECT_EQ(all->GetNumberOfFailedParts(), 1);
  EXPECT_EQ(stringField(out, arrays::PartName, 4), "open");
  EXPECT_EQ(intField(out, arrays::PartStatus, 4), 3);
  for (unsigned int i = 0; i < names.size(); ++i)
  {
    auto* mat = vtkPolyData::SafeDownCast(out->GetBlock(i));
    ASSERT_NE(mat, nullptr) << names[i];
    EXPECT_EQ(intField(out, arrays::PartStatus, i), 0) << names[i];
    vtkNew<vtkMAT25DFilter> one;
    one->SetInputData(vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(i)));
    one->SetLength(2.0);
    one->SetNumberOfThreads(1);
    one->Update();
    expectIdentical(one->GetOutput(), mat, names[i]);
  }
  auto* nestedOut = vtkMultiBlockDataSet::SafeDownCast(out->GetBlock(4));
  ASSERT_NE(nestedOut, nullptr);
  auto* empty = vtkPolyData::SafeDownCast(nestedOut->GetBlock(0));
  ASSERT_NE(empty, nullptr);
  EXPECT_EQ(empty->GetNumberOfPoints(), 0);
}

TEST(MATCollections, ThreadedVerificationGivesTheSequentialFigures)
{
  // The filters really run on two threads when asked (Debian's VTK defaults to one).
  EXPECT_EQ(exactmat::threadsFor(2), 2);
  EXPECT_EQ(exactmat::threadsFor(1), 1);
  for (const char* name : { "plate-with-holes", "spiral", "star" })
  {
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(name);
    double error[2];
    std::string report[2];
    int sheetCheck[2];
    double sweptError[2];
    for (int threads : { 1, 2 })
    {
      vtkNew<vtkMAT2DFilter> mat;
      mat->SetInputConnection(source->GetOutputPort());
      mat->SetNumberOfThreads(threads);
      mat->SetVerificationTolerance(0.0); // fails where the error is not 0: a report to compare too
      mat->Update();
      error[threads - 1] = mat->GetMaximumVerifiedError();
      report[threads - 1] = stringField(mat->GetOutput(), arrays::VerificationReport, 0);

      vtkNew<vtkMAT25DFilter> swept;
      swept->SetInputConnection(source->GetOutputPort());
      swept->SetNumberOfThreads(threads);
      swept->SetMaximumSheetPointsVerified(0);
      swept->Update();
      sheetCheck[threads - 1] = swept->GetNumberOfVerifiedPoints() * 1000 +
        swept->GetNumberOfTouchpointMismatches();
      sweptError[threads - 1] = swept->GetMaximumVerifiedError();
    }
    EXPECT_EQ(error[0], error[1]) << name;
    EXPECT_EQ(report[0], report[1]) << name;
    EXPECT_EQ(sheetCheck[0], sheetCheck[1]) << name;
    EXPECT_EQ(sweptError[0], sweptError[1]) << name;
    EXPECT_GT(sheetCheck[0], 1000) << name;
  }
}

TEST(MATCollections, SolidsThroughThe3DFilterWithOneItCannotDo)
{
  const std::vector<std::string> names = { "box", "extrusion", "notched-cube", "pillow" };
  vtkSmartPointer<vtkPartitionedDataSetCollection> collection = catalogueSolids(names);
  vtkNew<vtkMAT3DFilter> all;
  all->SetInputDataObject(collection);
  all->SetNumberOfThreads(2);
  all->Update();
  auto* out = vtkPartitionedDataSetCollection::SafeDownCast(all->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(all->GetNumberOfParts(), 4);
  EXPECT_EQ(all->GetNumberOfFailedParts(), 1);
  // The extruded blob's seams are reached only from its rims (fin points, not traced yet):
  // refused, by name, the others done.
  EXPECT_EQ(intField(out, arrays::PartStatus, 1), 3);
  EXPECT_NE(stringField(out, arrays::PartMessage, 1).find("3D MAT"), std::string::npos);
  int junctions = 0;
  for (unsigned int i : { 0u, 2u, 3u })
  {
    EXPECT_EQ(intField(out, arrays::PartStatus, i), 0) << names[i];
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(names[i].c_str());
    vtkNew<vtkMAT3DFilter> one;
    one->SetInputConnection(source->GetOutputPort());
    one->SetNumberOfThreads(1);
    one->Update();
    expectIdentical(one->GetOutput(), vtkPolyData::SafeDownCast(out->GetPartition(i, 0)), names[i]);
    EXPECT_EQ(one->GetMaximumVerifiedError(),
      vtkDataArray::SafeDownCast(out->GetFieldData()->GetArray(arrays::MaximumVerifiedError))->GetTuple1(i));
    junctions += one->GetNumberOfJunctions();
  }
  EXPECT_EQ(all->GetNumberOfJunctions(), junctions);
}

// The sheets of a collection of solids: vtkMAT3DFilter's collection output and the
// collection of solids as the source give each solid's own sheets and fits in its place;
// the solid whose seams failed is named and the others are filled, each as on its own.
TEST(MATCollections, SheetsOfACollectionOfSolids)
{
  const std::vector<std::string> names = { "box", "extrusion", "notched-cube" };
  vtkSmartPointer<vtkPartitionedDataSetCollection> collection = catalogueSolids(names);
  vtkNew<vtkMAT3DFilter> seams;
  seams->SetInputDataObject(collection);
  vtkNew<vtkSheetInterpolator> sheets;
  sheets->SetInputConnection(seams->GetOutputPort());
  sheets->SetSourceData(collection);
  sheets->SetNumberOfThreads(2);
  // The solids are filled concurrently (two threads); progress only grows, wave by wave.
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    static_cast<std::vector<double>*>(clientData)->push_back(*static_cast<double*>(callData));
  });
  sheets->AddObserver(vtkCommand::ProgressEvent, onProgress);
  sheets->Update();
  ASSERT_GE(progress.size(), 3u);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_EQ(progress.back(), 1.0);
  auto* out = vtkPartitionedDataSetCollection::SafeDownCast(sheets->GetOutputDataObject(0));
  auto* fits = vtkPartitionedDataSetCollection::SafeDownCast(sheets->GetOutputDataObject(1));
  ASSERT_NE(out, nullptr);
  ASSERT_NE(fits, nullptr);
  EXPECT_EQ(sheets->GetNumberOfParts(), 3);
  EXPECT_EQ(sheets->GetNumberOfFailedParts(), 1);
  EXPECT_FALSE(sheets->GetVerificationPassed());
  EXPECT_EQ(stringField(out, arrays::PartName, 1), "extrusion");
  EXPECT_EQ(intField(out, arrays::PartStatus, 1), 3);
  EXPECT_NE(stringField(out, arrays::PartMessage, 1).find("MAT is empty"), std::string::npos);
  int triangles = 0;
  for (unsigned int i : { 0u, 2u })
  {
    EXPECT_EQ(intField(out, arrays::PartStatus, i), 0) << names[i];
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(names[i].c_str());
    vtkNew<vtkMAT3DFilter> one;
    one->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkSheetInterpolator> alone;
    alone->SetInputConnection(one->GetOutputPort());
    alone->SetSourceConnection(source->GetOutputPort());
    alone->SetNumberOfThreads(1);
    alone->Update();
    ASSERT_TRUE(alone->GetVerificationPassed()) << names[i];
    expectIdentical(alone->GetOutput(), vtkPolyData::SafeDownCast(out->GetPartition(i, 0)), names[i]);
    auto* fit = vtkUnstructuredGrid::SafeDownCast(fits->GetPartition(i, 0));
    ASSERT_NE(fit, nullptr);
    EXPECT_EQ(fit->GetNumberOfCells(), alone->GetNumberOfFitPatches()) << names[i];
    EXPECT_GT(fit->GetNumberOfCells(), 0) << names[i];
    EXPECT_EQ(intField(out, "NumberOfTriangles", i), alone->GetNumberOfTriangles()) << names[i];
    triangles += alone->GetNumberOfTriangles();
  }
  EXPECT_EQ(sheets->GetNumberOfTriangles(), triangles);
  EXPECT_EQ(vtkPolyData::SafeDownCast(out->GetPartition(1, 0))->GetNumberOfPoints(), 0);

  // The wrong source (one solid for a collection of MATs) is refused, naming what it needs.
  vtkNew<vtkNURBSSource> box;
  box->SetShapeName("box");
  vtkNew<vtkSheetInterpolator> wrong;
  wrong->SetInputConnection(seams->GetOutputPort());
  wrong->SetSourceConnection(box->GetOutputPort());
  auto errors = ErrorRecorder::watch(wrong);
  wrong->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, vtkSmartPointer<ErrorRecorder>::New());
  wrong->Update();
  EXPECT_NE(errors->Messages.find("collection of solids"), std::string::npos) << errors->Messages;
}
