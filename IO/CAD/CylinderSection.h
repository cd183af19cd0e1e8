#ifndef CylinderSection_h
#define CylinderSection_h
/**
 * @file CylinderSection.h
 * @brief A cylinder's face cut off by planes, exactly: the face bounded by two rulings and,
 * across them, two planar sections of the cylinder (a circle at a fixed height, or an
 * ellipse where a slanted plane cuts it — two fillets meeting at a miter, a pipe cut at an
 * angle) is the ruled rational patch between the two sections.
 *
 * Each section is the image of one base circle under an affine map along the axis (the
 * projection onto the section's plane), and an affine image of a rational curve is the
 * curve of the mapped poles with the same weights and knots; so the two sections share the
 * circle's parameter, and the straight line between their points of one parameter is the
 * ruling there. Degree (2, 1), weights the circle's, no approximation.
 */

#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <string>
#include <vector>

namespace exactmat
{
/// One edge of a cut cylinder face, as an iso-line of its ruled patch.
struct CylinderSectionEdge
{
  TopoDS_Edge edge;
  bool isoV = true;  ///< a section (iso-line t = 0 or 1), else a ruling (s fixed)
  double fixed = 0.0;
};

struct CylinderSectionFace
{
  /// The ruled patch over (s, t): s the base circle's B-spline parameter, t ∈ [0, 1] from
  /// one section to the other.
  Handle(Geom_BSplineSurface) surface;
  std::vector<CylinderSectionEdge> edges;
};

/// The face as a ruled patch between two planar sections, or, when it is not one (another
/// surface, a trimming loop of another shape), `why` says what does not fit and the result
/// holds no surface. `tol` is the model's point tolerance.
CylinderSectionFace cylinderSectionFace(const TopoDS_Face& face, double tol, std::string& why);
} // namespace exactmat

#endif
