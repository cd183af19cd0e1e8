/**
 * @class   vtkNURBSReader
 * @brief   Reads an exact NURBS boundary from ExactMAT's JSON format (see NURBSJson.h and
 *          the README) into a vtkUnstructuredGrid of rational Bézier cells.
 *
 * The output has the same arrays as vtkNURBSSource: `RationalWeights`, `HigherOrderDegrees`,
 * `EdgeId`/`FaceId` (the index of the NURBS entity in the file, or its "id"), and
 * `ParameterRange`. A file that cannot be read, or holds an invalid NURBS, makes
 * RequestData fail with an error naming the file, the entry and the problem.
 *
 * @sa vtkNURBSWriter vtkNURBSSource
 */
#ifndef vtkNURBSReader_h
#define vtkNURBSReader_h

#include "ExactMATIONURBSModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class EXACTMATIONURBS_EXPORT vtkNURBSReader : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkNURBSReader* New();
  vtkTypeMacro(vtkNURBSReader, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The JSON file to read. Default: none.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

protected:
  vtkNURBSReader();
  ~vtkNURBSReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  vtkNURBSReader(const vtkNURBSReader&) = delete;
  void operator=(const vtkNURBSReader&) = delete;
};

#endif
