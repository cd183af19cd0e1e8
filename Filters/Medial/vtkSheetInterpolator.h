/**
 * @class   vtkSheetInterpolator
 * @brief   The medial sheets of a solid's 3D MAT as triangles with `Radius`: with
 *          vtkMAT3DFilter's seams and junctions, the complete MAT (thesis §6.3.9).
 *
 * Input port 0: vtkMAT3DFilter's output (the seam graph and, as field data, each sheet's
 * generator pair and bounding seams and convex edges), or vtkMAT25DFilter's (its swept,
 * profile and mid-sheets are exact already: they pass through unchanged, each sheet element
 * numbered in `SheetId` with `SheetStatus` 1 and its `Governors` in `SheetGovernors`, and
 * every point is verified against the source like the interpolated ones; the coverage
 * check needs touchpoints the 2.5D output does not carry and is skipped). Input port 1
 * (the source, as vtkProbeFilter takes it: SetSourceConnection / SetSourceData): the exact
 * boundary the MAT was computed from (for vtkMAT25DFilter: the swept solid, as
 * vtkNURBSSource's Sweep makes it).
 *
 * Output: one vtkPolyData — the input's junctions, seams and skeletal edges unchanged, and
 * every sheet as triangles sharing point ids with the seams on its border. Point data as
 * vtkMAT3DFilter's (`Radius`, `PointType` 0 for sheet points and 5 for radius 0 on a convex
 * edge, `Touchpoints` 2 inside a sheet, `Footpoint0`/`Footpoint1` the two touchpoints);
 * cell data `ElementType` (7 for sheet triangles), `ElementId`, `Governors` (the sheet's
 * pair, "0,4" or "3,12/13"), `SheetId` (the sheet's tuple in `SheetGovernors`, −1 for
 * the seam graph's cells). Field data: the input's sheet topology, `SheetStatus` per sheet
 * (1 interpolated, 0 empty: its balls meet in one point, −1 failed) and `SheetMessage` (why
 * it failed).
 *
 * Every sheet vertex is the centre of a ball touching both generators of the pair:
 * parameterised by the touchpoint on one of them (a face when the pair has one), the other
 * touch and the radius solved by Newton; triangles by CGAL's constrained Delaunay
 * triangulation of the parameter domain bounded by the seams' touchpoints, refined until
 * each triangle's centroid is within Tolerance of the exact sheet (position and radius)
 * and no edge is longer than MaximumEdgeLength. Coplanar faces across smooth edges (a
 * polygon split into triangles) are one side of a sheet.
 *
 * Output port 1 (FitSheets, default on): the thesis' "rational description to a defined
 * tolerance" — each interpolated sheet as a cubic B-spline surface of centre and radius,
 * fitted to the sheet's exact balls (sheets/SheetFit) and handed out as the data
 * contract's `VTK_BEZIER_QUADRILATERAL` cells (weights 1, `HigherOrderDegrees`), one per
 * knot-span rectangle the sheet reaches (the sheet is the part inside its triangles'
 * border loops, given as trimming loops; a cell may reach past them by less than its span).
 * Point data `Radius` holds the
 * radius function's Bézier coefficients, so the cells' own interpolation gives the fitted
 * radius. Cell data `SheetId`, `ParameterRange` (the cell's knot spans in the sheet's
 * [0,1]² parameter square) and `SheetFitError` (the sheet's largest error); field data
 * `SheetFitError` per sheet tuple (−1: not fitted) and the trimming: the sheets' border
 * loops in (s, t) (`SheetTrimLoops`, `SheetTrimLoopOffsets`, `SheetTrimLoopSheet`; the
 * sheet is the part inside its outer loop and outside its holes). The error — the larger of the centre's
 * and the radius's, a fraction of the solid's size — is measured at the sheet's vertices
 * and at exact balls between them the fit never saw (the triangles' centroids); spans are
 * halved until it is within FitTolerance (0: Tolerance). A sheet whose fit stays above it
 * (a cone point at a reflex edge's end is approximated, not represented) is named in a
 * warning and counted in NumberOfSheetsAboveFitTolerance. vtkMAT25DFilter's exact sheets
 * are not fitted (port 1 is empty for them).
 *
 * VerifyOutput (default on) checks every output point — or at most
 * MaximumSheetPointsVerified sheet points, evenly spread, when that is not 0 — against the
 * exact boundary: global distance = Radius, two touchpoints inside a sheet; and checks
 * completeness: the sheets' touchpoint footprints on every face add up to its area (each
 * boundary point has one maximal ball). A sheet that cannot be interpolated is named in a
 * warning and, like a face left uncovered, makes the verification fail: the output is
 * never an incomplete MAT that says it is complete.
 *
 * Collections: input 0 may be vtkMAT3DFilter's (or vtkMAT25DFilter's) output for a
 * vtkPartitionedDataSetCollection or vtkMultiBlockDataSet of solids, and the source the
 * collection of those solids (the same structure). Both outputs then have that structure,
 * each part's sheets and fits in its place; a part whose MAT is empty (its MAT filter
 * failed) or whose sheets fail gets empty outputs and does not stop the others. The first
 * output's field data carry one row per part as vtkMATAlgorithm's do (`PartName`,
 * `PartStatus`, `PartMessage`, `PartSeconds`, `MaximumVerifiedError`, and the counts:
 * `NumberOfSheets`, `NumberOfTriangles`, …); the getters hold the sums over the parts. In
 * a distributed run (one piece of several) each rank fills the parts it holds and the
 * rows are gathered, as vtkMATAlgorithm does.
 *
 * @warning Not yet complete: where a sheet's border has stretches that are neither seams nor
 * convex edges (the sheet goes on as another pair's across a side of a face), they are
 * closed by straight lines in the parameter domain; at some corners of reflex edges and
 * corners (the notched cube, staircases) that cuts a corner off or fails — the coverage
 * check reports the face. Smooth edges between curved faces are not joined into one side.
 */
#ifndef vtkSheetInterpolator_h
#define vtkSheetInterpolator_h

#include "ExactMATFiltersMedialModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <functional> // for FillPart
#include <string> // for PassExactSheets
#include <vector> // for PassExactSheets

class vtkCompositeDataSet;
class vtkUnstructuredGrid;
namespace exactmat
{
class Boundary3D;
class PatchBoundary;
struct MedialComplex;
struct Normalisation;
struct SheetFit;
struct VerificationOutcome;
}

class EXACTMATFILTERSMEDIAL_EXPORT vtkSheetInterpolator : public vtkPolyDataAlgorithm
{
public:
  static vtkSheetInterpolator* New();
  vtkTypeMacro(vtkSheetInterpolator, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The exact boundary (input port 1).
  void SetSourceConnection(vtkAlgorithmOutput* algOutput);
  void SetSourceData(vtkDataObject* source);

  /// Largest deviation of a triangle from the exact sheet (position and radius, at its
  /// centroid), a fraction of the solid's size.
  vtkSetClampMacro(Tolerance, double, 1e-9, 1e-1);
  vtkGetMacro(Tolerance, double);
  /// Longest triangle edge, a fraction of the solid's size.
  vtkSetClampMacro(MaximumEdgeLength, double, 1e-4, 1.0);
  vtkGetMacro(MaximumEdgeLength, double);

  vtkSetMacro(VerifyOutput, bool);
  vtkGetMacro(VerifyOutput, bool);
  vtkBooleanMacro(VerifyOutput, bool);
  vtkSetMacro(VerificationTolerance, double);
  vtkGetMacro(VerificationTolerance, double);
  /// 0 (default): every point is verified; else at most this many sheet points.
  vtkSetClampMacro(MaximumSheetPointsVerified, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumSheetPointsVerified, int);
  /// Threads (vtkSMPTools, STDThread backend; 0 = every core): the sheets are filled in
  /// parallel and verified in parallel, with the same result as on one thread.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);

  /// Fit each sheet with a B-spline surface (output port 1).
  vtkSetMacro(FitSheets, bool);
  vtkGetMacro(FitSheets, bool);
  vtkBooleanMacro(FitSheets, bool);
  /// Largest fit error (centre and radius), a fraction of the solid's size; 0: Tolerance.
  vtkSetClampMacro(FitTolerance, double, 0.0, 1e-1);
  vtkGetMacro(FitTolerance, double);

  vtkGetMacro(NumberOfSheets, int);
  vtkGetMacro(NumberOfInterpolatedSheets, int);
  vtkGetMacro(NumberOfFailedSheets, int);
  vtkGetMacro(NumberOfTriangles, int);
  vtkGetMacro(MaximumDeviation, double);
  vtkGetMacro(InterpolationSeconds, double);
  vtkGetMacro(VerificationSeconds, double);
  vtkGetMacro(NumberOfVerifiedPoints, int);
  vtkGetMacro(NumberOfTouchpointMismatches, int);
  /// The completeness check: the largest |footprint area − face area| / face area over the
  /// faces (the sheets' touchpoints on a face cover it once); above 10 × Tolerance the
  /// verification fails.
  vtkGetMacro(MaximumCoverageShortfall, double);
  vtkGetMacro(VerificationPassed, bool);
  /// The fits: Bézier cells on port 1, the largest error over the sheets (a fraction of the
  /// size), sheets whose fit stayed above FitTolerance, and the time they took.
  vtkGetMacro(NumberOfFitPatches, int);
  vtkGetMacro(MaximumFitError, double);
  vtkGetMacro(NumberOfSheetsAboveFitTolerance, int);
  vtkGetMacro(FitSeconds, double);
  vtkGetMacro(MaximumVerifiedError, double);
  /// A collection's parts in the last run, and how many of them failed (an error, or a
  /// failed verification); 1 and 0 or 1 for one solid.
  vtkGetMacro(NumberOfParts, int);
  vtkGetMacro(NumberOfFailedParts, int);

protected:
  vtkSheetInterpolator();
  ~vtkSheetInterpolator() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  virtual int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSheetInterpolator(const vtkSheetInterpolator&) = delete;
  void operator=(const vtkSheetInterpolator&) = delete;

  /// One solid's figures (and the warnings it raised), filled by FillPart on any thread.
  struct Figures;
  /// The getters' values from one solid's figures or a collection's sums.
  void PublishFigures(const Figures& figures);
  /// One solid's sheets into `output` and `fits`; the error that stopped it, or "".
  /// Reads only the settings: solids of a collection are filled concurrently.
  std::string FillPart(vtkPolyData* mat, vtkUnstructuredGrid* boundary, vtkPolyData* output,
    vtkUnstructuredGrid* fits, Figures& figures, const std::function<void(double)>& progress) const;
  int RequestCollection(vtkCompositeDataSet* mats, vtkCompositeDataSet* boundaries, vtkCompositeDataSet* output,
    vtkCompositeDataSet* fits, vtkInformationVector* outputVector);
  void Interpolate(vtkPolyData* mat, vtkUnstructuredGrid* boundary, vtkPolyData* output, vtkUnstructuredGrid* fits,
    Figures& figures, const std::function<void(double)>& progress) const;
  void WriteFits(const std::vector<exactmat::SheetFit>& fitted, const std::vector<std::string>& fitErrors,
    const std::vector<std::string>& labels, const std::vector<std::vector<int>>& tupleIds, int tuples,
    double tolerance, const exactmat::Normalisation& frame, vtkUnstructuredGrid* fits, Figures& figures) const;
  void PassExactSheets(vtkPolyData* mat, const exactmat::Boundary3D& boundary,
    const exactmat::MedialComplex& complex, const std::vector<std::string>& governors, vtkPolyData* output,
    Figures& figures) const;
  exactmat::VerificationOutcome VerifyPoints(const exactmat::PatchBoundary& exact,
    const exactmat::MedialComplex& complex, const exactmat::Normalisation& frame, Figures& figures) const;

  double Tolerance = 1e-4;
  double MaximumEdgeLength = 0.05;
  bool VerifyOutput = true;
  double VerificationTolerance = 1e-9;
  int MaximumSheetPointsVerified = 0;
  int NumberOfThreads = 0;
  bool FitSheets = true;
  double FitTolerance = 0.0;

  int NumberOfSheets = 0;
  int NumberOfInterpolatedSheets = 0;
  int NumberOfFailedSheets = 0;
  int NumberOfTriangles = 0;
  double MaximumDeviation = 0.0;
  double InterpolationSeconds = 0.0;
  double VerificationSeconds = 0.0;
  int NumberOfVerifiedPoints = 0;
  int NumberOfTouchpointMismatches = 0;
  double MaximumCoverageShortfall = 0.0;
  bool VerificationPassed = true;
  double MaximumVerifiedError = 0.0;
  int NumberOfFitPatches = 0;
  double MaximumFitError = 0.0;
  int NumberOfSheetsAboveFitTolerance = 0;
  double FitSeconds = 0.0;
  int NumberOfParts = 0;
  int NumberOfFailedParts = 0;
};

#endif
