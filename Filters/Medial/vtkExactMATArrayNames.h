#ifndef vtkExactMATArrayNames_h
#define vtkExactMATArrayNames_h
/**
 * @file vtkExactMATArrayNames.h
 * @brief The names of every array ExactMAT reads or writes, defined once.
 *
 * Input (boundary) arrays:
 * - `RationalWeights` (point data, double): weight of each control point; absent = all 1.
 * - `HigherOrderDegrees` (cell data, 3 components): degrees (p, q, 0) of Bézier cells;
 *   absent = deduced from the point count.
 * - `EdgeId` / `FaceId` (cell data, integer): the user entity (NURBS curve / surface) each
 *   Bézier cell belongs to; absent = the cell index.
 * - `ParameterRange` (cell data, 2 or 4 components): the knot span (t0, t1) or
 *   (u0, u1, v0, v1) of the cell in its entity, so a writer can rebuild the original NURBS.
 *
 * Output (MAT) arrays, point data: `Radius` (double): the radius of the maximal disk/ball;
 * `PointType` (int, see exactmat::MedialPointType: 0 normal, 1 branch, 2 end at a convex
 * vertex, 3 end at a centre of curvature, 4 cycle joint, 5 circle centre); `Footpoint0`,
 * `Footpoint1` (3-vectors): the touching points of the disk. Cell data: `SegmentId` (int,
 * −1 for node vertex cells), `Generator0`, `Generator1` (int: the EdgeId of the boundary
 * entity, −1 for a reflex corner), `Generators` (string: every generator of the cell,
 * e.g. "3,7,12" for a branch node; reflex corners as "v<vertex>").
 *
 * Solids (vtkMAT25DFilter), point data: `Radius`; `PointType` (int, see
 * exactmat::MedialPoint3DType: 0 sheet, 1 seam, 2 junction, 3 seam end, 4 skeletal edge,
 * 5 on a convex edge or vertex of the solid, 6 centre of a ball touching a circle, 7 centre
 * of a ball touching the whole boundary: a sphere's MAT);
 * `Touchpoints` (int: distinct touching points of the ball by construction, 0 = not
 * finite); vtkMAT3DFilter also `Footpoint0`, `Footpoint1`, `Footpoint2` (3-vectors: the
 * ball's touchpoints — a seam point's three, a junction's first three, the vertex on a rim
 * or at radius 0). Cell data: `ElementType` (int, see exactmat::MedialElementType: 0 junction,
 * 1 seam, 2 skeletal edge, 3 centre curve, 4 swept sheet, 5 profile sheet, 6 mid-sheet,
 * 7 sheet of a free-form solid, 8 a ball's centre, as a vertex cell: the whole MAT of a
 * sphere),
 * `ElementId`
 * (int: the element a cell belongs to), `SegmentId` (the profile MAT segment or node it
 * comes from), `Governors` (string: the boundary entities it is equidistant to, e.g.
 * "start,2,5"; "start"/"end" = the profile faces, "v<vertex>" = a reflex edge).
 *
 * Sheets of a solid's MAT (field data of vtkMAT3DFilter's output, one tuple per sheet):
 * `SheetGovernors` (string: the FaceIds of the sheet's face pair, "0,4"; a face that is one
 * of several cells under one FaceId — a CAD face tiled into patches — is "FaceId:cell",
 * "2:1"), `SheetSeams` (string: the ElementIds of the seams on its border, "5 9 12"),
 * `SheetConvexEdges` (string: the face pairs of the convex edges on its border, where its
 * radius is 0, "0/4").
 * vtkSheetInterpolator adds the sheets as triangles (`ElementType` 7) with cell data
 * `SheetId` (int: the sheet's tuple above, −1 for other cells) and field data
 * `SheetStatus` (int per tuple: 1 interpolated, 0 empty, −1 failed) and `SheetMessage`.
 * Its second output (the sheets' B-spline fits as Bézier cells) has point data `Radius`
 * (the radius's Bézier coefficients), cell data `SheetId` and `SheetFitError` (the sheet's
 * largest fit error / size), and `SheetFitError` per sheet tuple as field data (−1: none);
 * the sheets' trimming loops as field data: `SheetTrimLoops` (double, 2 components: every
 * loop's (s, t) points, loop after loop), `SheetTrimLoopOffsets` (int: where each loop
 * starts, and the total last) and `SheetTrimLoopSheet` (int: each loop's SheetId).
 *
 * Verification (field data of every MAT output, when VerifyOutput is on):
 * `VerificationStatus` (int: 1 passed, 0 failed — the filter also warns —, −1 not run),
 * `MaximumVerifiedError` (double: largest |distance to the exact boundary − Radius| / size),
 * `VerificationReport` (string: what failed and where, empty when passed); and the
 * filter's figures, one value each, named as its getters (`NumberOfSegments`,
 * `TracingSeconds`, …).
 *
 * A collection's summary (field data of a composite output, one value per part; see
 * vtkMATAlgorithm): `PartName`, `PartStatus` (int: 0 verified, 1 not verified, 2
 * verification failed, 3 failed), `PartMessage`, `PartSeconds`, `MaximumVerifiedError` and
 * every figure.
 */

namespace exactmat
{
namespace arrays
{
constexpr const char* RationalWeights = "RationalWeights";
constexpr const char* HigherOrderDegrees = "HigherOrderDegrees";
constexpr const char* EdgeId = "EdgeId";
constexpr const char* FaceId = "FaceId";
constexpr const char* ParameterRange = "ParameterRange";
constexpr const char* Radius = "Radius";
constexpr const char* PointType = "PointType";
constexpr const char* Footpoint0 = "Footpoint0";
constexpr const char* Footpoint1 = "Footpoint1";
constexpr const char* Footpoint2 = "Footpoint2";
constexpr const char* SegmentId = "SegmentId";
constexpr const char* Generator0 = "Generator0";
constexpr const char* Generator1 = "Generator1";
constexpr const char* Generators = "Generators";
constexpr const char* Touchpoints = "Touchpoints";
constexpr const char* ElementType = "ElementType";
constexpr const char* ElementId = "ElementId";
constexpr const char* Governors = "Governors";
constexpr const char* SheetGovernors = "SheetGovernors";
constexpr const char* SheetSeams = "SheetSeams";
constexpr const char* SheetConvexEdges = "SheetConvexEdges";
constexpr const char* SheetId = "SheetId";
constexpr const char* SheetStatus = "SheetStatus";
constexpr const char* SheetMessage = "SheetMessage";
constexpr const char* SheetFitError = "SheetFitError";
constexpr const char* SheetTrimLoops = "SheetTrimLoops";
constexpr const char* SheetTrimLoopOffsets = "SheetTrimLoopOffsets";
constexpr const char* SheetTrimLoopSheet = "SheetTrimLoopSheet";
constexpr const char* VerificationStatus = "VerificationStatus";
constexpr const char* MaximumVerifiedError = "MaximumVerifiedError";
constexpr const char* VerificationReport = "VerificationReport";
constexpr const char* PartName = "PartName";
constexpr const char* PartStatus = "PartStatus";
constexpr const char* PartMessage = "PartMessage";
constexpr const char* PartSeconds = "PartSeconds";
} // namespace arrays
} // namespace exactmat

#endif
