/**
 * @class   vtkNURBSWriter
 * @brief   Writes a boundary grid of Bézier cells as NURBS entities in ExactMAT's JSON
 *          format (see vtkNURBSReader).
 *
 * Curve cells of one `EdgeId` that join end to start are merged back into one NURBS curve
 * (knots from `ParameterRange` when present, then every joint knot removed as far as the
 * continuity allows), so reader → writer gives back the file's curves. Surface cells are
 * written one NURBS surface per cell (knots from `ParameterRange`); a Bézier triangle is
 * written as the equivalent tensor-product patch with one collapsed side. Numbers are
 * written so that they read back to the same doubles.
 */
#ifndef vtkNURBSWriter_h
#define vtkNURBSWriter_h

#include "ExactMATIONURBSModule.h" // for export macro
#include "vtkWriter.h"

class vtkUnstructuredGrid;

class EXACTMATIONURBS_EXPORT vtkNURBSWriter : public vtkWriter
{
public:
  static vtkNURBSWriter* New();
  vtkTypeMacro(vtkNURBSWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The JSON file to write. Default: none.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

protected:
  vtkNURBSWriter();
  ~vtkNURBSWriter() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  char* FileName = nullptr;

private:
  vtkNURBSWriter(const vtkNURBSWriter&) = delete;
  void operator=(const vtkNURBSWriter&) = delete;
};

#endif
