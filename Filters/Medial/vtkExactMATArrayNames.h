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
 * Output (MAT) arrays: `Radius` (point data, double): the radius of the maximal disk/ball.
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
} // namespace arrays
} // namespace exactmat

#endif
