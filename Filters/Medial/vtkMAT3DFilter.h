/**
 * @class   vtkMAT3DFilter
 * @brief   The seams and junctions of the medial axis transform of a solid bounded by exact
 *          rational Bézier faces (Ramanathan's thesis, ch. 6).
 *
 * Input: a closed solid as a vtkUnstructuredGrid of surface cells — rational Bézier
 * quadrilaterals and triangles (`VTK_BEZIER_QUADRILATERAL`, `VTK_BEZIER_TRIANGLE`) and
 * planar `VTK_QUAD` / `VTK_TRIANGLE` faces — conforming along shared edges, in either
 * orientation (vtkNURBSSource's 3D shapes, or a reader's output).
 *
 * Output: vtkPolyData whose points are exact MAT points: junctions (vertex cells; four or
 * more faces touch the ball) and seams (polylines from node to node; three faces touch),
 * which share their end points with the junctions and the convex vertices they start from:
 * the polydata is the seam graph. Point data `Radius`, `PointType` (1 seam, 2 junction,
 * 3 seam end at a convex vertex, radius 0), `Touchpoints` (distinct boundary points the
 * ball touches; 0 at radius 0). Cell data `ElementType` (0 junction, 1 seam), `ElementId`,
 * `Governors` (the FaceIds of the faces the element is equidistant to, e.g. "0,2,4").
 * Field data: the medial sheets' topology, one tuple per sheet — `SheetGovernors` (its
 * face pair), `SheetSeams` (the ElementIds of the seams on its border), `SheetConvexEdges`
 * (the convex edges on its border, as face pairs "a/b"); see vtkExactMATArrayNames.h.
 *
 * The seams are traced from the convex vertices by continuation on the exact ball
 * equations (every touchpoint parameter, centre and radius unknown), steps controlled by
 * Tolerance; after every step the ball is tested for emptiness against the whole exact
 * boundary, and junctions are located by bisection and polished to rounding. Computed in
 * a normalised frame (centred, unit size): the result does not depend on where the solid
 * sits or how large it is.
 *
 * VerifyOutput checks every output point against the exact boundary (global distance =
 * Radius, the number of touchpoints); a failure warns, sets VerificationPassed false and
 * the output's field data (`VerificationStatus`, `VerificationReport`).
 *
 * Besides seams and junctions: skeletal edges (rims of curved faces, where a ball
 * osculates a ridge: the ellipsoid; and where the sheet of two reflex edges closes at their
 * corner), centre curves (balls touching a whole circle: a cylinder's axis, a torus' core)
 * and, for a ball, its centre alone (`PointType` 7, `ElementType` 8 vertex cell: every face
 * on one sphere). The sheets themselves are filled by vtkSheetInterpolator.
 *
 * @warning Supported today: solids with convex, reflex and smooth edges and reflex corners
 * that have a vertex with a convex edge — polyhedra (notched, stepped, staircases) and
 * free-form solids such as the catalogue's pillow — and the rims, circles and spheres
 * above. Not yet: rims that meet seams (fin points), fillets, solids whose seams no vertex,
 * rim or circle leads to (see the README's limits): the filter fails with an error naming
 * the face or edge, never with a partial MAT.
 */
#ifndef vtkMAT3DFilter_h
#define vtkMAT3DFilter_h

#include "ExactMATFiltersMedialModule.h" // for export macro
#include "vtkMATAlgorithm.h"

class EXACTMATFILTERSMEDIAL_EXPORT vtkMAT3DFilter : public vtkMATAlgorithm
{
public:
  static vtkMAT3DFilter* New();
  vtkTypeMacro(vtkMAT3DFilter, vtkMATAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Largest deviation of a seam's polyline from the seam, as a fraction of the solid's
  /// size (adaptive steps). Default 1e-4.
  vtkSetClampMacro(Tolerance, double, 1e-12, 1e-1);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Longest step along a seam, a fraction of the solid's size: the spacing of the ball-
  /// emptiness checks that find junctions. Default 0.05.
  vtkSetClampMacro(MaximumStep, double, 1e-6, 0.5);
  vtkGetMacro(MaximumStep, double);
  ///@}

  ///@{
  /// Fixed-step mode (reproduces the thesis): a constant tracing step along the seams and the
  /// spacing of the junction (ball-emptiness) checks, fractions of the solid's size.
  /// Defaults: off, 1e-3, 1e-2.
  vtkSetMacro(FixedStep, bool);
  vtkGetMacro(FixedStep, bool);
  vtkBooleanMacro(FixedStep, bool);
  vtkSetClampMacro(Step, double, 1e-9, 1e-1);
  vtkGetMacro(Step, double);
  vtkSetClampMacro(JunctionCheckStep, double, 1e-9, 1.0);
  vtkGetMacro(JunctionCheckStep, double);
  ///@}

  ///@{
  /// Results of the last run (sums over a collection's parts).
  vtkGetMacro(NumberOfJunctions, int);
  vtkGetMacro(NumberOfSeams, int);
  /// Rims: skeletal edges where a sheet of two reflex edges closes at their common corner.
  vtkGetMacro(NumberOfSkeletalEdges, int);
  /// Curves of centres of balls touching a face along a whole circle: a cylinder's axis,
  /// a torus' core (CentreCurve polylines of CircleCentre points).
  vtkGetMacro(NumberOfCentreCurves, int);
  /// Parts that are balls (every face on one sphere): their MAT is the centre alone.
  vtkGetMacro(NumberOfSphereCentres, int);
  /// Nodes of the seam graph with the wrong number of seams (a junction of four touchpoints
  /// meets four): the graph's own check, part of the verification (0 when it passes).
  vtkGetMacro(NumberOfTopologyProblems, int);
  vtkGetMacro(NumberOfSheets, int);
  vtkGetMacro(NumberOfVerifiedPoints, int);
  vtkGetMacro(NumberOfTouchpointMismatches, int);
  /// Verified points whose touchpoint search ran out of its box limit short of the touch
  /// (balls osculating a free-form face next to a pole): their distance is proved by their
  /// recorded touch at the radius and the emptiness of the ball shrunk by 1e-12 of the
  /// size — exact, but their touch count is then the construction's, not re-counted.
  vtkGetMacro(NumberOfWitnessedPoints, int);
  vtkGetMacro(TracingSeconds, double);
  vtkGetMacro(VerificationSeconds, double);
  ///@}

protected:
  vtkMAT3DFilter();
  ~vtkMAT3DFilter() override;

  void ComputePart(vtkUnstructuredGrid* input, vtkPolyData* output, exactmat::PartResult& result,
    const std::function<void(double)>& progress) const override;
  void PublishFigures(const exactmat::PartResult& figures) override;

  double Tolerance = 1e-4;
  double MaximumStep = 0.05;
  bool FixedStep = false;
  double Step = 1e-3;
  double JunctionCheckStep = 1e-2;
  int NumberOfJunctions = 0;
  int NumberOfSeams = 0;
  int NumberOfSkeletalEdges = 0;
  int NumberOfCentreCurves = 0;
  int NumberOfSphereCentres = 0;
  int NumberOfTopologyProblems = 0;
  int NumberOfSheets = 0;
  int NumberOfVerifiedPoints = 0;
  int NumberOfTouchpointMismatches = 0;
  int NumberOfWitnessedPoints = 0;
  double TracingSeconds = 0.0;
  double VerificationSeconds = 0.0;

private:
  vtkMAT3DFilter(const vtkMAT3DFilter&) = delete;
  void operator=(const vtkMAT3DFilter&) = delete;
};

#endif
