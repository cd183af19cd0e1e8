/**
 * @class   vtkMAT2DFilter
 * @brief   The medial axis transform of a planar domain bounded by exact NURBS curves.
 *
 * Input: a vtkUnstructuredGrid of boundary curves (rational `VTK_BEZIER_CURVE` cells,
 * `VTK_LINE`, `VTK_POLY_LINE`; see vtkNURBSSource), one or more closed loops in any plane,
 * holes allowed, either orientation. Output: the MAT as vtkPolyData whose points are MAT
 * points, with one polyline per simplified segment (point ids shared at branch points, so
 * the polydata is the medial graph) and a vertex cell per graph node.
 *
 * Point data: `Radius` (the radius function), `PointType` (0 normal, 1 branch, 2 end at a
 * convex vertex, 3 end at a centre of curvature, 4 cycle joint, 5 circle centre),
 * `Footpoint0`, `Footpoint1` (where the disk touches the boundary). Cell data: `SegmentId`
 * (−1 on node vertex cells), `Generator0`, `Generator1` (the boundary entities, by EdgeId,
 * of the segment's first point; −1 for a reflex corner), `Generators` (string, all of a
 * node's generators). See vtkExactMATArrayNames.h.
 *
 * The algorithm traces the MAT along the boundary (Ramanathan's thesis, ch. 4): every
 * point is equidistant to its footpoints on the exact curves, the disk is checked empty
 * against the exact boundary, branch points are polished to rounding. Steps are adaptive
 * (Tolerance bounds the distance between the polyline and the true MAT) or fixed
 * (FixedStep with Step and BranchCheckStep, as in the thesis).
 *
 * @warning Bad input (open or self-intersecting loops, non-planar curves, NaN, weights ≤ 0,
 * surface cells, an empty grid) makes RequestData fail with an error naming the cell.
 */
#ifndef vtkMAT2DFilter_h
#define vtkMAT2DFilter_h

#include "ExactMATFiltersMedialModule.h" // for export macro
#include "vtkMATAlgorithm.h"

class EXACTMATFILTERSMEDIAL_EXPORT vtkMAT2DFilter : public vtkMATAlgorithm
{
public:
  static vtkMAT2DFilter* New();
  vtkTypeMacro(vtkMAT2DFilter, vtkMATAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Adaptive mode: the largest distance between the traced polyline (and its interpolated
   * radius) and the true MAT, as a fraction of the boundary's bounding-box diagonal.
   * Default 1e-4.
   */
  vtkSetClampMacro(Tolerance, double, 1e-12, 1e-1);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Fixed-step mode (reproduces the thesis): constant tracing step and branch-check step as
   * fractions of the domain size. Defaults: off, 1e-3, 1e-2.
   */
  vtkSetMacro(FixedStep, bool);
  vtkGetMacro(FixedStep, bool);
  vtkBooleanMacro(FixedStep, bool);
  vtkSetClampMacro(Step, double, 1e-9, 1e-1);
  vtkGetMacro(Step, double);
  vtkSetClampMacro(BranchCheckStep, double, 1e-9, 1.0);
  vtkGetMacro(BranchCheckStep, double);
  ///@}

  ///@{
  /// Results of the last run (sums over a collection's parts): the numbers of segments,
  /// branch points and end points. The verification (vtkMATAlgorithm) also checks
  /// footpoint counts, that the footpoints sweep the boundary once, one connected component
  /// per connected domain and cycles = holes.
  vtkGetMacro(NumberOfSegments, int);
  vtkGetMacro(NumberOfBranchPoints, int);
  vtkGetMacro(NumberOfEndPoints, int);
  /// Seconds spent, apart: setting up the exact boundary (loops, orientation, the
  /// crossing check, generators and their tree), tracing the MAT, writing it into the
  /// output's points, cells and arrays, and verifying it.
  vtkGetMacro(SetUpSeconds, double);
  vtkGetMacro(TracingSeconds, double);
  vtkGetMacro(OutputSeconds, double);
  vtkGetMacro(VerificationSeconds, double);
  ///@}

protected:
  vtkMAT2DFilter();
  ~vtkMAT2DFilter() override;

  void ComputePart(vtkUnstructuredGrid* input, vtkPolyData* output, exactmat::PartResult& result,
    const std::function<void(double)>& progress) const override;
  void PublishFigures(const exactmat::PartResult& figures) override;

  double Tolerance = 1e-4;
  bool FixedStep = false;
  double Step = 1e-3;
  double BranchCheckStep = 1e-2;

  int NumberOfSegments = 0;
  int NumberOfBranchPoints = 0;
  int NumberOfEndPoints = 0;
  double SetUpSeconds = 0.0;
  double TracingSeconds = 0.0;
  double OutputSeconds = 0.0;
  double VerificationSeconds = 0.0;

private:
  vtkMAT2DFilter(const vtkMAT2DFilter&) = delete;
  void operator=(const vtkMAT2DFilter&) = delete;
};

#endif
