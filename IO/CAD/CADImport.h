#ifndef CADImport_h
#define CADImport_h
/**
 * @file CADImport.h
 * @brief STEP and IGES parts as exact rational Bézier boundaries, through OpenCASCADE.
 *
 * Every curve and surface is converted exactly (no tessellation): lines, conics, Bézier and
 * B-spline curves become rational Bézier pieces; planes, cylinders, cones, spheres, tori,
 * surfaces of revolution and extrusion of such curves, Bézier and B-spline surfaces become
 * rational Bézier patches. Offset and other curves or surfaces with no exact rational form
 * are refused with an InputError naming the edge or face.
 *
 * A solid's faces are tiled so that the patches conform along every shared edge (what
 * Boundary3D requires): each edge carries a set of split points, every face tiles itself
 * with patch corners at its edges' split points, and the split points a face needs (its
 * knots, where an iso-line meets an edge) are given to the face across that edge, until no
 * face needs a new one. Three kinds of faces are tiled:
 * - faces with natural bounds (every edge an iso-parameter line on the border of the
 *   face's parameter rectangle, a seam, or a pole): the surface's Bézier patches, cut at the
 *   split points by exact knot insertion;
 * - planar faces bounded by straight and curved edges (holes allowed): a rational Bézier
 *   triangle (a cap) between each curved piece and an apex on the material side, and linear
 *   triangles over the polygon of the straight pieces and the caps' apexes (CGAL's
 *   constrained triangulation, no new vertices); curved pieces are cut until each cap holds
 *   its curve and no cap meets another part of the face;
 * - planar discs bounded by one closed circle or ellipse: rational quadratic Bézier
 *   triangles (sectors) from the conic's centre, one per piece of the rim.
 * Any other trimmed face is refused with an error naming it.
 *
 * Entity ids are OpenCASCADE's indices in the part (TopExp::MapShapes order, from 0).
 */

#include "nurbs/BezierCurve.h"
#include "nurbs/BezierPatch.h"

#include <map>
#include <string>
#include <vector>

namespace exactmat
{

struct CADImportOptions
{
  int dimension = 0; ///< 0: a solid when the file has one (or its faces close up), else 2D
  int part = 0;      ///< which solid (3D) or planar face (2D), in file order
  std::string partName; ///< when set, the solid or face of this name (overrides part)
};

struct CADBoundary
{
  int dimension = 2;
  struct Curve
  {
    BezierCurve curve;
    int edge = -1;
    double t0 = 0.0, t1 = 1.0; ///< span of the edge's curve (file parameterisation)
  };
  struct Patch
  {
    BezierPatch patch;
    int face = -1;
    double u0 = 0.0, u1 = 1.0, v0 = 0.0, v1 = 1.0;
  };
  struct Triangle
  {
    TriangleNet net;
    int face = -1;
  };
  std::vector<Curve> curves;
  std::vector<Patch> patches;
  std::vector<Triangle> triangles;

  std::string format;     ///< "STEP" or "IGES"
  std::string lengthUnit; ///< the unit of the coordinates (the file's), e.g. "MM", "INCH"
  int partCount = 0;      ///< solids (3D) or planar faces (2D) in the file
  std::vector<std::string> partNames; ///< the solids' names in the file ("" when unnamed); faces' only when a face is asked for by name
  std::string partName;   ///< the name of the part read
  std::map<int, Vec3> faceColours; ///< RGB in [0, 1] of the faces the file colours (by FaceId)
  int faceCount = 0, edgeCount = 0; ///< of the part read
  /// OpenCASCADE's findings while translating the file (its shape healing: "#114: Poor
  /// result from projection vertex / curve 3d"), warnings and fails, in entity order: what
  /// the translator changed or doubted on the way to the shapes read.
  std::vector<std::string> translatorMessages;
};

/// Reads `fileName` (.step/.stp or .iges/.igs, case-insensitive). Throws InputError naming
/// the file, and the face or edge, for anything it cannot read exactly.
CADBoundary importCAD(const std::string& fileName, const CADImportOptions& options = {});

} // namespace exactmat

#endif
