/**
 * @class   vtkCADBoundaryReader
 * @brief   Reads a part from a STEP or IGES file (through OpenCASCADE) as an exact boundary:
 *          a vtkUnstructuredGrid of rational Bézier cells, nothing tessellated.
 *
 * A solid gives rational Bézier quadrilaterals and triangles (and linear triangles for
 * planar faces bounded by straight edges) that conform along every shared edge, for
 * vtkMAT3DFilter; a planar face, wire or sketch gives rational Bézier curves, for
 * vtkMAT2DFilter. `FaceId` / `EdgeId` are OpenCASCADE's indices of the part's faces / edges
 * (TopExp::MapShapes order, from 0); every cell also carries `ParameterRange`, the span of
 * the file's parameterisation it covers, and `FaceColor` (RGB in [0, 1], NaN where none)
 * when the file colours faces or parts. Field data: `LengthUnit` (the file's unit, in which
 * the coordinates are given), `SourceFormat` ("STEP"/"IGES"), `NumberOfParts`,
 * `PartNames` (the names the file gives its solids, or faces in 2D) and `PartName`.
 *
 * Supported exactly: lines, conics, Bézier and B-spline curves; planes, cylinders, cones,
 * spheres, tori, surfaces of revolution and extrusion, Bézier and B-spline surfaces whose
 * faces are bounded by their parameter rectangles; planar faces bounded by straight edges
 * (holes allowed) or by one whole circle or ellipse. Anything else (offset curves and
 * surfaces, other trimmed faces, open shells) makes RequestData fail with an error naming
 * the file and the face or edge.
 *
 * @sa vtkNURBSReader vtkMAT2DFilter vtkMAT3DFilter
 */
#ifndef vtkCADBoundaryReader_h
#define vtkCADBoundaryReader_h

#include "ExactMATIOCADModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class EXACTMATIOCAD_EXPORT vtkCADBoundaryReader : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkCADBoundaryReader* New();
  vtkTypeMacro(vtkCADBoundaryReader, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .step/.stp or .iges/.igs file to read. Default: none.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// 0 (default): a solid when the file has one (loose faces that close up count), else a
  /// planar face or the file's wires; 2: a planar face or wires; 3: a solid.
  vtkSetClampMacro(Dimension, int, 0, 3);
  vtkGetMacro(Dimension, int);
  ///@}

  ///@{
  /// Which solid (3D) or planar face (2D) of the file, in file order. Default 0.
  vtkSetClampMacro(PartIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(PartIndex, int);
  ///@}

  ///@{
  /// When set (non-empty), the solid (3D) or face (2D) the file names so, instead of
  /// PartIndex; an unknown name is an error listing the file's names. Default: none.
  vtkSetStringMacro(PartName);
  vtkGetStringMacro(PartName);
  ///@}

  /// After an update: the parts (solids or faces) in the file, and the unit read.
  vtkGetMacro(NumberOfParts, int);
  vtkGetStringMacro(LengthUnit);
  /// After an update: OpenCASCADE's warnings and fails while translating the file (its
  /// shape healing), also warned and kept as field data `TranslatorMessages`.
  vtkGetMacro(NumberOfTranslatorMessages, int);

  /// True when the file name ends in .step, .stp, .iges or .igs (any case).
  static bool CanReadFile(const char* fileName);

protected:
  vtkCADBoundaryReader();
  ~vtkCADBoundaryReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkSetStringMacro(LengthUnit);

  char* FileName = nullptr;
  int Dimension = 0;
  int PartIndex = 0;
  int NumberOfParts = 0;
  int NumberOfTranslatorMessages = 0;
  char* LengthUnit = nullptr;
  char* PartName = nullptr;

private:
  vtkCADBoundaryReader(const vtkCADBoundaryReader&) = delete;
  void operator=(const vtkCADBoundaryReader&) = delete;
};

#endif
