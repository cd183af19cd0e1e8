#include "vtkMATCollection.h"

#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataObjectTree.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPartitionedDataSetCollection.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnstructuredGrid.h>

namespace exactmat
{
namespace
{
// A tree iterator over every leaf, null ones included, in flat-index order.
vtkSmartPointer<vtkCompositeDataIterator> leafIterator(vtkCompositeDataSet* collection, bool skipEmpty)
{
  vtkSmartPointer<vtkCompositeDataIterator> it = vtk::TakeSmartPointer(collection->NewIterator());
  if (auto* tree = vtkDataObjectTreeIterator::SafeDownCast(it))
  {
    tree->VisitOnlyLeavesOn();
    tree->TraverseSubTreeOn();
  }
  it->SetSkipEmptyNodes(skipEmpty);
  return it;
}
} // namespace

std::vector<CollectionPart> collectionParts(vtkCompositeDataSet* collection)
{
  std::vector<CollectionPart> parts;
  if (auto* pdc = vtkPartitionedDataSetCollection::SafeDownCast(collection))
  {
    for (unsigned int i = 0; i < pdc->GetNumberOfPartitionedDataSets(); ++i)
    {
      vtkPartitionedDataSet* pds = pdc->GetPartitionedDataSet(i);
      if (!pds)
        continue;
      std::string name = "part " + std::to_string(i);
      if (pdc->HasMetaData(i) && pdc->GetMetaData(i)->Has(vtkCompositeDataSet::NAME()))
        name = pdc->GetMetaData(i)->Get(vtkCompositeDataSet::NAME());
      const unsigned int n = pds->GetNumberOfPartitions();
      for (unsigned int j = 0; j < n; ++j)
        if (vtkDataObject* leaf = pds->GetPartitionAsDataObject(j))
        {
          CollectionPart part;
          part.data = leaf;
          part.name = n > 1 ? name + " #" + std::to_string(j) : name;
          part.place.partitioned = true;
          part.place.dataset = i;
          part.place.partition = j;
          parts.push_back(std::move(part));
        }
    }
    return parts;
  }
  vtkSmartPointer<vtkCompositeDataIterator> it = leafIterator(collection, true);
  int k = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem(), ++k)
  {
    CollectionPart part;
    part.data = it->GetCurrentDataObject();
    part.name = "part " + std::to_string(k);
    if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
      part.name = it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
    part.place.flatIndex = it->GetCurrentFlatIndex();
    parts.push_back(std::move(part));
  }
  return parts;
}

vtkDataObject* partAt(vtkCompositeDataSet* collection, const PartPlace& place)
{
  if (!collection)
    return nullptr;
  if (place.partitioned)
  {
    auto* pdc = vtkPartitionedDataSetCollection::SafeDownCast(collection);
    if (!pdc || place.dataset >= pdc->GetNumberOfPartitionedDataSets())
      return nullptr;
    vtkPartitionedDataSet* pds = pdc->GetPartitionedDataSet(place.dataset);
    return pds && place.partition < pds->GetNumberOfPartitions() ? pds->GetPartitionAsDataObject(place.partition)
                                                                 : nullptr;
  }
  vtkSmartPointer<vtkCompositeDataIterator> it = leafIterator(collection, true);
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    if (it->GetCurrentFlatIndex() == place.flatIndex)
      return it->GetCurrentDataObject();
  return nullptr;
}

void setPartAt(vtkCompositeDataSet* collection, const PartPlace& place, vtkDataObject* part)
{
  if (place.partitioned)
  {
    if (auto* pdc = vtkPartitionedDataSetCollection::SafeDownCast(collection))
      pdc->SetPartition(place.dataset, place.partition, part);
    return;
  }
  vtkSmartPointer<vtkCompositeDataIterator> it = leafIterator(collection, false);
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    if (it->GetCurrentFlatIndex() == place.flatIndex)
    {
      collection->SetDataSet(it, part);
      return;
    }
}

vtkMultiProcessController* distributedController(vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector ? outputVector->GetInformationObject(0) : nullptr;
  if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) ||
    info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) < 2)
    return nullptr;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller && controller->GetNumberOfProcesses() > 1 ? controller : nullptr;
}

bool isEmptyGrid(vtkDataObject* part)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(part);
  return grid && grid->GetNumberOfCells() == 0;
}

} // namespace exactmat
