#ifndef OCCTTestParts_h
#define OCCTTestParts_h
/**
 * @file OCCTTestParts.h
 * @brief Parts built with OpenCASCADE for the STEP/IGES tests and the reading benchmark.
 */

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Face.hxx>

#include <cmath>
#include <tuple>

namespace exactmat
{
namespace testparts
{
// A planar profile bounded by a B-spline (a wave on top) and three lines.
inline TopoDS_Face waveProfile()
{
  TColgp_Array1OfPnt poles(1, 5);
  poles(1) = gp_Pnt(2, 0, 0);
  poles(2) = gp_Pnt(2, 0.8, 0);
  poles(3) = gp_Pnt(1.2, 1.4, 0);
  poles(4) = gp_Pnt(0.5, 0.9, 0);
  poles(5) = gp_Pnt(0.3, 1.2, 0);
  TColStd_Array1OfReal knots(1, 3);
  knots(1) = 0;
  knots(2) = 0.5;
  knots(3) = 1;
  TColStd_Array1OfInteger mults(1, 3);
  mults(1) = 4;
  mults(2) = 1;
  mults(3) = 4;
  Handle(Geom_BSplineCurve) wave = new Geom_BSplineCurve(poles, knots, mults, 3);
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(0.3, 0, 0), gp_Pnt(2, 0, 0)));
  wire.Add(BRepBuilderAPI_MakeEdge(wave));
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(0.3, 1.2, 0), gp_Pnt(0.3, 0, 0)));
  return BRepBuilderAPI_MakeFace(wire.Wire());
}
// A 4 × 2 × 3 box with two edges that meet at a corner filleted with one radius:
// OpenCASCADE miters them, each cylinder cut where they meet by a slanted plane (an ellipse).
inline TopoDS_Shape boxWithMiteredFillets(double radius = 0.4)
{
  TopoDS_Shape box = BRepPrimAPI_MakeBox(4, 2, 3).Shape();
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(box, TopAbs_EDGE, edges);
  const TopoDS_Edge first = TopoDS::Edge(edges(1));
  BRepFilletAPI_MakeFillet fillet(box);
  fillet.Add(radius, first);
  for (int k = 2; k <= edges.Extent(); ++k)
  {
    const TopoDS_Edge e = TopoDS::Edge(edges(k));
    if (TopExp::FirstVertex(e).IsSame(TopExp::FirstVertex(first)))
    {
      fillet.Add(radius, e);
      break;
    }
  }
  return fillet.Shape();
}

// A rod of radius 1 cut at an angle at both ends: its side a cylinder between two
// ellipses (and its seam), its ends elliptic discs.
inline TopoDS_Shape rodCutAtAngles()
{
  TopoDS_Shape rod = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0.3, -0.2, -3), gp_Dir(0, 0, 1)), 1.0, 6.0).Shape();
  for (const auto& [angle, z, above] : { std::tuple{ 0.5, 1.8, true }, std::tuple{ -0.3, -2.1, false } })
  {
    gp_Trsf turn;
    turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, z), gp_Dir(1, 0.2, 0)), angle);
    const TopoDS_Shape slab = BRepPrimAPI_MakeBox(gp_Pnt(-5, -5, above ? z : z - 10), 10, 10, 10).Shape();
    rod = BRepAlgoAPI_Cut(rod, BRepBuilderAPI_Transform(slab, turn).Shape()).Shape();
  }
  return rod;
}
// A 4 × 3 × 1 plate with a hole of radius 0.4 drilled through its middle at `tilt` radians
// from the normal (about y): the hole's wall a cylinder between two ellipses.
inline TopoDS_Shape plateWithAngledHole(double tilt)
{
  const TopoDS_Shape plate = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 4, 3, 1).Shape();
  const gp_Dir axis(std::sin(tilt), 0, std::cos(tilt));
  const TopoDS_Shape drill = BRepPrimAPI_MakeCylinder(
    gp_Ax2(gp_Pnt(2 - 2 * std::sin(tilt), 1.5, 0.5 - 2.5 * std::cos(tilt)), axis), 0.4, 5).Shape();
  return BRepAlgoAPI_Cut(plate, drill).Shape();
}
} // namespace testparts
} // namespace exactmat

#endif
