#include "CylinderSection.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Circ.hxx>
#include <gp_Elips.hxx>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace exactmat
{
namespace
{
/// The plane n·x = d of a section, n turned along the axis.
struct SectionPlane
{
  gp_Vec n;
  double d = 0.0;
  std::vector<TopoDS_Edge> edges;
};

/// The base circle's poles moved along `axis` onto the plane (same weights and knots).
Handle(Geom_BSplineCurve) onPlane(const Handle(Geom_BSplineCurve) & base, const SectionPlane& plane, const gp_Vec& axis)
{
  Handle(Geom_BSplineCurve) c = Handle(Geom_BSplineCurve)::DownCast(base->Copy());
  const double along = plane.n.Dot(axis);
  for (int i = 1; i <= c->NbPoles(); ++i)
  {
    const gp_Pnt p = c->Pole(i);
    const double h = (plane.d - plane.n.Dot(gp_Vec(p.XYZ()))) / along;
    c->SetPole(i, p.Translated(h * axis));
  }
  return c;
}
/// The plane of a B-spline or Bézier edge whose poles lie on one (IGES stores conics so).
bool planeOfPoles(const BRepAdaptor_Curve& curve, double tol, gp_Ax1& normal)
{
  std::vector<gp_Pnt> poles;
  if (curve.GetType() == GeomAbs_BSplineCurve)
  {
    const Handle(Geom_BSplineCurve) b = curve.BSpline();
    for (int i = 1; i <= b->NbPoles(); ++i)
    {
      poles.push_back(b->Pole(i));
    }
  }
  else if (curve.GetType() == GeomAbs_BezierCurve)
  {
    const Handle(Geom_BezierCurve) b = curve.Bezier();
    for (int i = 1; i <= b->NbPoles(); ++i)
    {
      poles.push_back(b->Pole(i));
    }
  }
  if (poles.size() < 3)
  {
    return false;
  }
  // Three poles far apart span the plane: the first, the farthest from it, and the
  // farthest from the line through those two.
  const gp_Pnt a = poles[0];
  const gp_Pnt b = *std::max_element(poles.begin(), poles.end(),
    [&](const gp_Pnt& p, const gp_Pnt& q) { return a.Distance(p) < a.Distance(q); });
  const gp_Vec ab(a, b);
  const gp_Pnt c = *std::max_element(poles.begin(), poles.end(), [&](const gp_Pnt& p, const gp_Pnt& q) {
    return gp_Vec(a, p).Crossed(ab).Magnitude() < gp_Vec(a, q).Crossed(ab).Magnitude();
  });
  const gp_Vec n = ab.Crossed(gp_Vec(a, c));
  if (n.Magnitude() <= tol * ab.Magnitude())
  {
    return false;
  }
  const gp_Dir d(n);
  for (const gp_Pnt& p : poles)
  {
    if (std::abs(gp_Vec(a, p).Dot(gp_Vec(d))) > 10 * tol)
    {
      return false;
    }
  }
  normal = gp_Ax1(a, d);
  return true;
}
} // namespace

CylinderSectionFace cylinderSectionFace(const TopoDS_Face& face, double tol, std::string& why)
{
  CylinderSectionFace result;
  BRepAdaptor_Surface adaptor(face);
  if (adaptor.GetType() != GeomAbs_Cylinder)
  {
    why = "not a cylinder";
    return result;
  }
  int wires = 0;
  for (TopExp_Explorer ex(face, TopAbs_WIRE); ex.More(); ex.Next())
  {
    ++wires;
  }
  if (wires != 1)
  {
    why = "a cylinder with " + std::to_string(wires) + " trimming loops";
    return result;
  }
  const gp_Vec axis(adaptor.Cylinder().Axis().Direction());
  // Sort the edges: rulings (straight, along the axis, at a fixed angle u) and sections
  // (circles and ellipses, grouped by their planes).
  std::vector<std::pair<TopoDS_Edge, double>> rulings;
  std::vector<SectionPlane> planes;
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
  {
    const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
    if (BRep_Tool::Degenerated(e))
    {
      why = "a cylinder with a degenerate edge";
      return result;
    }
    BRepAdaptor_Curve curve(e);
    if (curve.GetType() == GeomAbs_Line)
    {
      if (gp_Vec(curve.Line().Direction()).Crossed(axis).Magnitude() > 1e-9)
      {
        why = "a cylinder with a straight edge that is not a ruling";
        return result;
      }
      double a, b;
      Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(e, face, a, b);
      if (pc.IsNull())
      {
        why = "a cylinder with an edge that has no parameter curve";
        return result;
      }
      rulings.push_back({ e, pc->Value(0.5 * (a + b)).X() });
      continue;
    }
    gp_Ax1 normal;
    gp_Pnt origin;
    if (curve.GetType() == GeomAbs_Circle)
    {
      normal = curve.Circle().Axis();
    }
    else if (curve.GetType() == GeomAbs_Ellipse)
    {
      normal = curve.Ellipse().Axis();
    }
    else if (!planeOfPoles(curve, tol, normal))
    {
      why = "a cylinder with an edge that is neither a ruling nor a planar curve";
      return result;
    }
    gp_Vec n(normal.Direction());
    if (n.Dot(axis) < 0.0)
    {
      n.Reverse();
    }
    if (n.Dot(axis) < 1e-6)
    {
      why = "a cylinder cut by a plane along its axis";
      return result;
    }
    const double d = n.Dot(gp_Vec(normal.Location().XYZ()));
    auto same = std::find_if(planes.begin(), planes.end(), [&](const SectionPlane& p) {
      return (p.n - n).Magnitude() <= 1e-9 && std::abs(p.d - d) <= 10 * tol;
    });
    if (same == planes.end())
    {
      planes.push_back({ n, d, {} });
      same = planes.end() - 1;
    }
    same->edges.push_back(e);
  }
  if (planes.size() != 2)
  {
    why = "a cylinder with edges on " + std::to_string(planes.size()) + " section planes (two are traced)";
    return result;
  }
  double u0 = 0.0, u1 = 0.0;
  if (!rulings.empty())
  {
    auto [lo, hi] = std::minmax_element(rulings.begin(), rulings.end(),
      [](const auto& a, const auto& b) { return a.second < b.second; });
    u0 = lo->second;
    u1 = hi->second;
  }
  for (const auto& r : rulings)
  {
    if (std::min(std::abs(r.second - u0), std::abs(r.second - u1)) > 1e-9 * (1.0 + std::abs(r.second)))
    {
      why = "a cylinder with rulings at more than two angles";
      return result;
    }
  }
  if (rulings.empty() || u1 - u0 < 1e-9 || u1 - u0 > 2 * M_PI * (1.0 + 1e-12))
  {
    why = "a cylinder not bounded by two of its rulings";
    return result;
  }
  Handle(Geom_Curve) circle = BRep_Tool::Surface(face)->VIso(0.0);
  Handle(Geom_BSplineCurve) base =
    GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(circle, u0, u1), Convert_TgtThetaOver2);
  if (base->IsPeriodic())
  {
    base->SetNotPeriodic();
  }
  Handle(Geom_BSplineCurve) sides[2] = { onPlane(base, planes[0], axis), onPlane(base, planes[1], axis) };
  // The sections must not meet inside the face: the ruling from one to the other keeps its
  // direction (the height difference a + b cos u + c sin u keeps its sign).
  const double s0 = base->FirstParameter(), s1 = base->LastParameter();
  double low = INFINITY, high = -INFINITY;
  for (int k = 0; k <= 64; ++k)
  {
    const double s = s0 + (s1 - s0) * k / 64.0;
    const double h = gp_Vec(sides[0]->Value(s), sides[1]->Value(s)).Dot(axis);
    low = std::min(low, h);
    high = std::max(high, h);
  }
  if (low <= 10 * tol && high >= -10 * tol)
  {
    why = "a cylinder whose two section planes meet on it";
    return result;
  }
  const int bottom = high < 0.0 ? 1 : 0;
  // Each plane's edges are its section, whole and nothing else.
  for (int k = 0; k < 2; ++k)
  {
    const Handle(Geom_BSplineCurve)& side = sides[k];
    std::vector<std::pair<double, double>> spans;
    for (const TopoDS_Edge& e : planes[k].edges)
    {
      BRepAdaptor_Curve curve(e);
      double ends[2];
      for (int j = 0; j <= 8; ++j)
      {
        const gp_Pnt p = curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * j / 8.0);
        GeomAPI_ProjectPointOnCurve projection(p, side);
        if (projection.NbPoints() == 0 || projection.LowerDistance() > 100 * tol)
        {
          std::ostringstream text;
          text << "a cylinder with an edge off the section of its plane";
          if (projection.NbPoints() > 0)
          {
            text << " by " << projection.LowerDistance();
          }
          why = text.str();
          return result;
        }
        if (j % 8 == 0)
        {
          ends[j / 8] = projection.LowerDistanceParameter();
        }
      }
      spans.push_back(std::minmax(ends[0], ends[1]));
      result.edges.push_back({ e, true, k == bottom ? 0.0 : 1.0 });
    }
    // ... one after the other from ruling to ruling (gaps compared as points).
    std::sort(spans.begin(), spans.end());
    double reached = s0;
    for (const auto& span : spans)
    {
      if (side->Value(reached).Distance(side->Value(span.first)) > 100 * tol)
      {
        why = "a cylinder whose section edges leave a gap or overlap";
        return result;
      }
      reached = span.second;
    }
    if (side->Value(reached).Distance(side->Value(s1)) > 100 * tol)
    {
      why = "a cylinder whose section edges do not reach its rulings";
      return result;
    }
  }
  // The rulings run from section to section at their angle.
  for (const double u : { u0, u1 })
  {
    const double s = u == u0 ? s0 : s1;
    const gp_Pnt a = sides[bottom]->Value(s), b = sides[1 - bottom]->Value(s);
    const gp_Vec span(a, b);
    double covered = 0.0;
    for (const auto& r : rulings)
    {
      if (std::abs(r.second - u) > 1e-9 * (1.0 + std::abs(u)))
      {
        continue;
      }
      BRepAdaptor_Curve curve(r.first);
      for (const double c : { curve.FirstParameter(), curve.LastParameter() })
      {
        const gp_Vec q(a, curve.Value(c));
        if (q.Crossed(span).Magnitude() > 100 * tol * span.Magnitude())
        {
          why = "a cylinder with a ruling off its parameter's line";
          return result;
        }
      }
      covered += curve.LastParameter() - curve.FirstParameter();
      result.edges.push_back({ r.first, false, s });
    }
    if (std::abs(covered - span.Magnitude()) > 100 * tol)
    {
      why = "a cylinder whose rulings do not run from one section to the other";
      return result;
    }
  }
  // The ruled patch: degree (p, 1), row t = 0 the bottom section, t = 1 the top.
  const int n = base->NbPoles();
  TColgp_Array2OfPnt poles(1, n, 1, 2);
  TColStd_Array2OfReal weights(1, n, 1, 2);
  for (int i = 1; i <= n; ++i)
  {
    poles(i, 1) = sides[bottom]->Pole(i);
    poles(i, 2) = sides[1 - bottom]->Pole(i);
    weights(i, 1) = weights(i, 2) = base->Weight(i);
  }
  TColStd_Array1OfReal uKnots(1, base->NbKnots());
  TColStd_Array1OfInteger uMults(1, base->NbKnots());
  base->Knots(uKnots);
  base->Multiplicities(uMults);
  TColStd_Array1OfReal vKnots(1, 2);
  TColStd_Array1OfInteger vMults(1, 2);
  vKnots(1) = 0.0;
  vKnots(2) = 1.0;
  vMults(1) = vMults(2) = 2;
  result.surface = new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, base->Degree(), 1);
  return result;
}
} // namespace exactmat
