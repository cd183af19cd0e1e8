/**
 * @class   vtkMAT25DFilter
 * @brief   The medial axis transform of an extruded or revolved solid, from the exact MAT
 *          of its planar profile.
 *
 * Input: the profile, as for vtkMAT2DFilter (a vtkUnstructuredGrid of closed boundary
 * curves: rational `VTK_BEZIER_CURVE`, `VTK_LINE`, `VTK_POLY_LINE` cells in one plane,
 * holes allowed). The sweep: an **extrusion** by Length along the profile plane's normal
 * (+z for a profile in z = 0), or a **revolution** by Angle degrees (up to and including
 * 360) about the axis through AxisOrigin along AxisDirection, which must lie in the
 * profile's plane and outside the profile (right-handed about AxisDirection).
 * vtkNURBSSource makes the matching solid (its Sweep settings) for display.
 *
 * Output: the MAT of the solid as vtkPolyData (Ramanathan's thesis, ch. 5): junction
 * points (vertex cells), seams, skeletal edges and, for circular profiles, the curve of
 * ball centres (polylines), and the medial sheets (triangles): each profile MAT segment
 * swept between its seams, and the sheets between each profile face and a side. A 360°
 * revolution has no profile faces: its MAT is the revolved 2D MAT.
 *
 * Point data: `Radius` (the ball radius), `PointType` (0 sheet, 1 seam, 2 junction,
 * 3 seam end, 4 skeletal edge, 5 on a convex edge/vertex of the solid (radius 0),
 * 6 centre of a ball touching a whole circle), `Touchpoints` (how many distinct points of
 * the boundary the ball touches; 0 when not a finite number). Cell data: `ElementType`
 * (0 junction, 1 seam, 2 skeletal edge, 3 centre curve, 4 swept sheet, 5 profile sheet,
 * 6 mid-sheet between the profile faces),
 * `ElementId` (cells of one element share it), `SegmentId` (the profile MAT segment or
 * node it comes from), `Governors` (string: the boundary entities the element is
 * equidistant to: the EdgeId of the profile edge a side face sweeps, "start"/"end" for the
 * profile faces, "v<vertex>" for the edge a reflex profile vertex sweeps).
 *
 * Every vertex is an exact MAT point: the profile's MAT points are exact to rounding, and
 * the sweep moves them exactly. VerifyOutput checks them against the exact swept boundary
 * (global distance = Radius, touchpoint counts) — every junction, seam, seam-end and
 * skeletal-edge point, and sheet points evenly spread up to MaximumSheetPointsVerified.
 *
 * Spans shorter than the thesis' method needs (Length < 2·Rmax; Angle < 2·asin(r/x)) are
 * handled: the MAT then has a mid-sheet between the two profile faces, bounded by seams
 * touching both faces and one side, with junctions where the profile MAT crosses it.
 *
 * @warning Axes that cross the profile or leave its plane, lengths ≤ 0, angles outside
 * (0, 360] and bad profiles make RequestData fail with an error that names the problem.
 */
#ifndef vtkMAT25DFilter_h
#define vtkMAT25DFilter_h

#include "ExactMATFiltersMedialModule.h" // for export macro
#include "vtkMATAlgorithm.h"

class EXACTMATFILTERSMEDIAL_EXPORT vtkMAT25DFilter : public vtkMATAlgorithm
{
public:
  static vtkMAT25DFilter* New();
  vtkTypeMacro(vtkMAT25DFilter, vtkMATAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SweepTypes
  {
    Extrusion = 0,
    Revolution = 1
  };

  ///@{
  /// Extrusion (default) or Revolution.
  vtkSetClampMacro(SweepType, int, Extrusion, Revolution);
  vtkGetMacro(SweepType, int);
  void SetSweepTypeToExtrusion() { this->SetSweepType(Extrusion); }
  void SetSweepTypeToRevolution() { this->SetSweepType(Revolution); }
  ///@}

  ///@{
  /// Extrusion length along the profile plane's normal. Default 3.
  vtkSetMacro(Length, double);
  vtkGetMacro(Length, double);
  ///@}

  ///@{
  /// Revolution: the angle in degrees, (0, 360] (default 360), and the axis (default: the
  /// y axis through the origin).
  vtkSetMacro(Angle, double);
  vtkGetMacro(Angle, double);
  vtkSetVector3Macro(AxisOrigin, double);
  vtkGetVector3Macro(AxisOrigin, double);
  vtkSetVector3Macro(AxisDirection, double);
  vtkGetVector3Macro(AxisDirection, double);
  ///@}

  ///@{
  /// The profile's 2D MAT, as in vtkMAT2DFilter: adaptive Tolerance (default 1e-4), or
  /// FixedStep with Step and BranchCheckStep (fractions of the profile size).
  vtkSetClampMacro(Tolerance, double, 1e-12, 1e-1);
  vtkGetMacro(Tolerance, double);
  vtkSetMacro(FixedStep, bool);
  vtkGetMacro(FixedStep, bool);
  vtkBooleanMacro(FixedStep, bool);
  vtkSetClampMacro(Step, double, 1e-9, 1e-1);
  vtkGetMacro(Step, double);
  vtkSetClampMacro(BranchCheckStep, double, 1e-9, 1.0);
  vtkGetMacro(BranchCheckStep, double);
  ///@}

  ///@{
  /// Spacing of sheet vertices across the sweep and from the boundary to the seams, as a
  /// fraction of the solid's size. Default 0.02.
  vtkSetClampMacro(SheetResolution, double, 1e-4, 0.5);
  vtkGetMacro(SheetResolution, double);
  ///@}

  ///@{
  /// How many sheet points at most the verification against the exact swept boundary
  /// (vtkMATAlgorithm) checks (default 500; the curves' points are always all checked).
  /// Every checked point must also have the number of touchpoints `Touchpoints` says.
  vtkSetClampMacro(MaximumSheetPointsVerified, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumSheetPointsVerified, int);
  ///@}

  ///@{
  /// Results of the last run (sums over a collection's parts): counts, how many verified
  /// points have another number of touchpoints than `Touchpoints` says, and the seconds
  /// spent on the profile's 2D MAT and on the construction in 3D.
  vtkGetMacro(NumberOfJunctions, int);
  vtkGetMacro(NumberOfSeams, int);
  vtkGetMacro(NumberOfSkeletalEdges, int);
  vtkGetMacro(NumberOfSheets, int);
  vtkGetMacro(NumberOfVerifiedPoints, int);
  vtkGetMacro(NumberOfTouchpointMismatches, int);
  vtkGetMacro(ProfileSeconds, double);
  vtkGetMacro(ConstructionSeconds, double);
  ///@}

protected:
  vtkMAT25DFilter();
  ~vtkMAT25DFilter() override;

  void ComputePart(vtkUnstructuredGrid* input, vtkPolyData* output, exactmat::PartResult& result,
    const std::function<void(double)>& progress) const override;
  void PublishFigures(const exactmat::PartResult& figures) override;

  int SweepType = Extrusion;
  double Length = 3.0;
  double Angle = 360.0;
  double AxisOrigin[3] = { 0.0, 0.0, 0.0 };
  double AxisDirection[3] = { 0.0, 1.0, 0.0 };
  double Tolerance = 1e-4;
  bool FixedStep = false;
  double Step = 1e-3;
  double BranchCheckStep = 1e-2;
  double SheetResolution = 0.02;
  int MaximumSheetPointsVerified = 500;

  int NumberOfJunctions = 0;
  int NumberOfSeams = 0;
  int NumberOfSkeletalEdges = 0;
  int NumberOfSheets = 0;
  int NumberOfVerifiedPoints = 0;
  int NumberOfTouchpointMismatches = 0;
  double ProfileSeconds = 0.0;
  double ConstructionSeconds = 0.0;

private:
  vtkMAT25DFilter(const vtkMAT25DFilter&) = delete;
  void operator=(const vtkMAT25DFilter&) = delete;
};

#endif
