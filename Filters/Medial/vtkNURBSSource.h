/**
 * @class   vtkNURBSSource
 * @brief   Exact free-form boundaries (rational Bézier cells) from a catalogue of named
 *          shapes or from user-defined NURBS curves and surfaces.
 *
 * The output is a vtkUnstructuredGrid of `VTK_BEZIER_CURVE` cells (2D domains, in z = 0,
 * material on the left of every curve) or `VTK_BEZIER_QUADRILATERAL` cells (closed solids,
 * normals pointing out), obtained from the NURBS entities by exact Bézier extraction. Arrays:
 * point data `RationalWeights`; cell data `HigherOrderDegrees` (p, q, 0), `EdgeId` (2D) or
 * `FaceId` (3D) = the index of the NURBS entity, `ParameterRange` = the cell's knot span.
 *
 * Catalogue (Shape): rectangle, rounded-rectangle, circle, ellipse, annulus, l-shape, star,
 * blob, spiral, plate-with-holes, narrow-passage (2D); box, cylinder, pillow, extrusion,
 * revolution, notched-cube, stepped-block (3D). Which parameters each uses is listed at SetShape(). Shape = UserDefined
 * outputs the entities given with AddCurve() / AddSurface().
 *
 * The output is checked: the boundary must form closed loops (2D) or a closed surface (3D);
 * otherwise RequestData fails with an error naming the entity.
 *
 * @sa vtkNURBSReader
 */
#ifndef vtkNURBSSource_h
#define vtkNURBSSource_h

#include "ExactMATFiltersMedialModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkDoubleArray;
class vtkPoints;

class EXACTMATFILTERSMEDIAL_EXPORT vtkNURBSSource : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkNURBSSource* New();
  vtkTypeMacro(vtkNURBSSource, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Shapes
  {
    Rectangle = 0,        ///< Width × Height, centred (5-segment MAT)
    RoundedRectangle,     ///< Width × Height, CornerRadius (tangent-continuous junctions)
    Circle,               ///< Radius (no convex vertex)
    Ellipse,              ///< semi-axes Width/2, Height/2
    Annulus,              ///< Radius, InnerRadius (a hole; no convex vertex)
    LShape,               ///< Width, Height, Thickness (one reflex corner)
    Star,                 ///< Count points, Radius, InnerRadius (Count reflex corners)
    Blob,                 ///< Radius, Count lobes (closed C² cubic; several LMPC points)
    Spiral,               ///< Radius (pitch); a 2.25-turn strip
    PlateWithHoles,       ///< Width × Height plate with three free-form holes
    NarrowPassage,        ///< Radius: two disks joined by a channel 0.3·Radius wide
    Box,                  ///< Width × Height × Length
    Cylinder,             ///< Radius, Length
    Pillow,               ///< Radius: a cube of bulging bicubic faces
    Extrusion,            ///< Radius, Length: the blob profile extruded
    Revolution,           ///< Radius: the blob profile revolved 360° about z
    NotchedCube,          ///< Width: the cube with its (+, +, +) eighth cut away (reflex edges, corner)
    SteppedBlock,         ///< Width × Height × Length: a base and a half-size block on top
    UserDefined = 100     ///< the entities added with AddCurve() / AddSurface()
  };

  ///@{
  /**
   * The shape to produce (a value of Shapes). Default: Rectangle.
   */
  vtkSetClampMacro(Shape, int, Rectangle, UserDefined);
  vtkGetMacro(Shape, int);
  ///@}

  ///@{
  /**
   * The shape by its catalogue name ("rectangle", "l-shape", …, or "user"). An unknown
   * name is an error and leaves the shape unchanged; returns false then.
   */
  bool SetShapeName(const char* name);
  const char* GetShapeName() const;
  ///@}

  /// Number of catalogue shapes and the name of shape i (for menus and loops in tests).
  static int GetNumberOfCatalogueShapes();
  static const char* GetCatalogueShapeName(int i);

  ///@{
  /// Shape parameters; defaults Width 4, Height 2, Length 3, Radius 1, InnerRadius 0.5,
  /// CornerRadius 0.4, Thickness 1, Count 5.
  vtkSetMacro(Width, double);
  vtkGetMacro(Width, double);
  vtkSetMacro(Height, double);
  vtkGetMacro(Height, double);
  vtkSetMacro(Length, double);
  vtkGetMacro(Length, double);
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  vtkSetMacro(InnerRadius, double);
  vtkGetMacro(InnerRadius, double);
  vtkSetMacro(CornerRadius, double);
  vtkGetMacro(CornerRadius, double);
  vtkSetMacro(Thickness, double);
  vtkGetMacro(Thickness, double);
  vtkSetMacro(Count, int);
  vtkGetMacro(Count, int);
  ///@}

  enum Sweeps
  {
    SweepNone = 0,       ///< the shape itself
    SweepExtrusion = 1,  ///< a 2D shape extruded by Length along its plane's normal
    SweepRevolution = 2  ///< a 2D shape revolved by SweepAngle about the sweep axis
  };

  ///@{
  /**
   * Sweep a 2D shape (catalogue or user curves) into the solid vtkMAT25DFilter computes
   * the MAT of: the side faces exactly (profile piece × line, or × rational quadratic arcs
   * of ≤ 90°) and the two profile faces tiled exactly by planar ruled patches along the
   * profile's medial strips, conforming along every shared edge. FaceId: a side carries
   * its profile curve's EdgeId; the start and end profile faces the next two ids.
   * Defaults: SweepNone, SweepAngle 360 (degrees), axis through the origin along y.
   */
  vtkSetClampMacro(Sweep, int, SweepNone, SweepRevolution);
  vtkGetMacro(Sweep, int);
  vtkSetMacro(SweepAngle, double);
  vtkGetMacro(SweepAngle, double);
  vtkSetVector3Macro(SweepAxisOrigin, double);
  vtkGetVector3Macro(SweepAxisOrigin, double);
  vtkSetVector3Macro(SweepAxisDirection, double);
  vtkGetVector3Macro(SweepAxisDirection, double);
  ///@}

  /**
   * Adds a NURBS curve (Shape = UserDefined): degree, knot vector (control points + degree
   * + 1 values), control points, and weights (nullptr = all 1). Checked when the output is
   * produced; an invalid curve makes RequestData fail with a message naming it.
   */
  void AddCurve(int degree, vtkDoubleArray* knots, vtkPoints* points, vtkDoubleArray* weights);

  /**
   * Adds a NURBS surface (Shape = UserDefined): degrees, knot vectors, a countU × countV net
   * of control points ordered with v fastest (index i·countV + j), weights (nullptr = all 1).
   */
  void AddSurface(int degreeU, int degreeV, vtkDoubleArray* knotsU, vtkDoubleArray* knotsV,
    int countU, int countV, vtkPoints* points, vtkDoubleArray* weights);

  /// Removes every user-defined entity.
  void RemoveAllEntities();

protected:
  vtkNURBSSource();
  ~vtkNURBSSource() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Shape = Rectangle;
  double Width = 4.0;
  double Height = 2.0;
  double Length = 3.0;
  double Radius = 1.0;
  double InnerRadius = 0.5;
  double CornerRadius = 0.4;
  double Thickness = 1.0;
  int Count = 5;
  int Sweep = SweepNone;
  double SweepAngle = 360.0;
  double SweepAxisOrigin[3] = { 0.0, 0.0, 0.0 };
  double SweepAxisDirection[3] = { 0.0, 1.0, 0.0 };

private:
  vtkNURBSSource(const vtkNURBSSource&) = delete;
  void operator=(const vtkNURBSSource&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
