#ifndef vtkMATCollection_h
#define vtkMATCollection_h
/**
 * @file vtkMATCollection.h
 * @brief The parts of a collection as the MAT filters see them: each leaf of a
 * vtkPartitionedDataSetCollection (one part per partition of each partitioned dataset)
 * or of a vtkMultiBlockDataSet (nested blocks too), its name and its place — so that a
 * filter can find the same part in a second input and put its result at the same place
 * in an output of the same structure, on every rank of a distributed run alike.
 */

#include <string>
#include <vector>

class vtkCompositeDataSet;
class vtkDataObject;
class vtkInformationVector;
class vtkMultiProcessController;

namespace exactmat
{

/// Where a part sits: (dataset, partition) in a partitioned collection, else the
/// composite flat index. The same in every dataset of the same structure.
struct PartPlace
{
  bool partitioned = false;
  unsigned int dataset = 0, partition = 0;
  unsigned int flatIndex = 0;
  /// A number that orders the places as the collection does.
  long long key() const
  {
    return partitioned ? (static_cast<long long>(dataset) << 24) + partition : flatIndex;
  }
};

struct CollectionPart
{
  vtkDataObject* data = nullptr;
  std::string name; ///< the NAME metadata (with " #j" for one of several partitions), else "part N"
  PartPlace place;
};

/// The non-null leaves of `collection`, in its order.
std::vector<CollectionPart> collectionParts(vtkCompositeDataSet* collection);

/// The leaf at `place` in a collection of the same structure (null if there is none).
vtkDataObject* partAt(vtkCompositeDataSet* collection, const PartPlace& place);

/// Puts `part` at `place` in `collection` (which has the structure the place came from).
void setPartAt(vtkCompositeDataSet* collection, const PartPlace& place, vtkDataObject* part);

/// The MPI controller when the request asks for one piece of several (ParaView spreading
/// data over pvserver or pvbatch ranks; `UpdatePiece(rank, ranks, 0)`), else null.
vtkMultiProcessController* distributedController(vtkInformationVector* outputVector);

/// A vtkUnstructuredGrid without cells: in a distributed run, another rank's part.
bool isEmptyGrid(vtkDataObject* part);

} // namespace exactmat

#endif
