#pragma once
/// @file Catalogue.h
/// @brief Named test shapes with exact NURBS boundaries, covering the cases of thesis
/// chapters 4–6, and the conversion of any NURBS boundary to B-rep input pieces.
///
/// 2D shapes lie in z = 0 with the material on the left of every curve (outer loops
/// counter-clockwise, holes clockwise). 3D shapes are closed, with outward normals.

#include "brep/Boundary2D.h"
#include "brep/Boundary3D.h"
#include "nurbs/NurbsCurve.h"
#include "nurbs/NurbsSurface.h"

#include <string>
#include <vector>

namespace exactmat
{

/// Parameters of the catalogue shapes. Each shape documents which it uses.
struct ShapeParameters
{
  double width = 4.0;        ///< x extent (rectangle, rounded rectangle, ellipse 2a, L, plate, box, notched cube)
  double height = 2.0;       ///< y extent (same shapes; ellipse 2b)
  double length = 3.0;       ///< z extent of box, cylinder and extrusion
  double radius = 1.0;       ///< circle, annulus outer, star outer, cylinder, lobes, blob mean
  double innerRadius = 0.5;  ///< annulus inner, star inner
  double cornerRadius = 0.4; ///< rounded rectangle corners
  double thickness = 1.0;    ///< L-shape leg width, narrow passage width
  int count = 5;             ///< star points, blob lobes
};

/// A boundary made of NURBS entities: curves (2D) or surfaces (3D). Entity ids are the
/// indices in these vectors.
struct Shape
{
  std::string name;
  int dimension = 2;
  std::vector<NurbsCurve> curves;
  std::vector<NurbsSurface> surfaces;
};

/// Names accepted by makeShape, 2D first: rectangle, rounded-rectangle, circle, ellipse,
/// annulus, l-shape, star, blob, spiral, plate-with-holes, narrow-passage, box, cylinder,
/// pillow, extrusion, revolution, notched-cube (edge = width, the (+, +, +) eighth cut away),
/// stepped-block (a width × height × length/2 base and a half-size block centred on top),
/// box-with-cavity (the box with a cubic cavity of edge thickness, moved off centre along x
/// by (width − thickness)/8), ellipsoid (semi-axes width/2, height/2, length/2; its MAT is a
/// sheet bounded by a rim, no seam), torus (about z: core radius width/2, tube radius
/// thickness/2; its MAT is the core circle). New names go last: the ParaView plugin numbers
/// them.
const std::vector<std::string>& catalogueNames();

/// Builds the named shape; throws InputError for an unknown name or parameters that make
/// no valid shape (naming the parameter).
Shape makeShape(const std::string& name, const ShapeParameters& parameters = {});

/// The rational Bézier pieces of every curve (entity = curve index), in order. Validates
/// each curve (InputError names it).
std::vector<CurvePiece> curvePieces(const std::vector<NurbsCurve>& curves);

/// The rational Bézier patches of every surface (entity = surface index).
std::vector<PatchPiece> patchPieces(const std::vector<NurbsSurface>& surfaces);

} // namespace exactmat
