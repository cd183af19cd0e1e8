#ifndef vtkMATPartSummary_h
#define vtkMATPartSummary_h
/**
 * @file vtkMATPartSummary.h
 * @brief A collection's summary, one row per part: what each part is called, what became
 * of it and its figures. When ParaView (or any pipeline asking for pieces) spreads a
 * collection over MPI ranks, each rank computes the parts it holds; the rows are then
 * gathered so that every rank's output carries the whole collection's summary.
 */

#include "vtkMATPartResult.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkDataArray;
class vtkFieldData;
class vtkMultiProcessController;

namespace exactmat
{

struct PartRow
{
  /// The part's place in the collection's structure, the same on every rank.
  long long key = 0;
  std::string name;
  /// 0 verified, 1 computed but not verified, 2 verification failed, 3 failed; −1: the
  /// part is not on this rank (a null or empty leaf: another rank's share).
  int status = -1;
  std::string message;
  double seconds = 0.0;
  double maximumError = 0.0;
  std::vector<PartFigure> figures;
};

/// Every rank's rows merged by key, in key order, on every rank (a collective call: each
/// rank of `controller` must make it). A part computed on several ranks (a source that gave
/// every rank the whole collection) keeps the lowest rank's row; a part absent from every
/// rank becomes a failed row, "no boundary cells on any rank". Without a controller of
/// more than one process the local rows come back, absent parts failed alike.
std::vector<PartRow> gatherPartRows(vtkMultiProcessController* controller, const std::vector<PartRow>& local);

/// An empty array for a figure, named as it: vtkIntArray for a count, vtkDoubleArray else.
vtkSmartPointer<vtkDataArray> newFigureArray(const PartFigure& figure);

/// The summary arrays (PartName, PartStatus, PartMessage, PartSeconds,
/// MaximumVerifiedError, then every figure any part has, in the order parts first name
/// them) added to `fieldData`.
void attachPartSummary(vtkFieldData* fieldData, const std::vector<PartRow>& rows);

} // namespace exactmat

#endif
