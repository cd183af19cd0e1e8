#ifndef OCCTTestParts_h
#define OCCTTestParts_h
/**
 * @file OCCTTestParts.h
 * @brief Parts built with OpenCASCADE for the STEP/IGES tests and the reading benchmark.
 */

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Face.hxx>

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
} // namespace testparts
} // namespace exactmat

#endif
