// The peer: OpenCASCADE's 2D bisecting locus (BRepMAT2d_BisectingLocus) on the same
// catalogue shapes and issue 14's polygons, timed the same way as ExactMAT (best of 21 runs
// from the curves to the MAT, set-up included). OpenCASCADE gets its native input, as a user would give it: consecutive pieces
// on one line, circle or ellipse become one line segment, arc or whole conic; only
// free-form pieces stay Bézier curves. (The column "OCCT, Bézier" hands it every piece as a
// rational Bézier curve, as ExactMAT sees them, for comparison.) Prints a Markdown table.
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepMAT2d_BisectingLocus.hxx>
#include <BRepMAT2d_Explorer.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeArcOfEllipse.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <gp_Circ.hxx>
#include <gp_Elips.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Dir2d.hxx>
#include <MAT_Graph.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include <Eigen/Dense>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace exactmat;

namespace
{
template <typename F>
double bestMs(int repeats, F f)
{
  double best = 1e300;
  for (int k = 0; k < repeats; ++k)
  {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

// The line, circle or ellipse a piece lies on (rational quadratics in standard form: the
// conic's centre is (M − w²P1)/(1 − w²), M the chord's mid-point), or Free.
struct Carrier
{
  enum Kind
  {
    Line,
    Circle,
    Ellipse,
    Free
  } kind = Free;
  gp_Pnt2d centre;
  gp_Dir2d major;
  double a = 0.0, b = 0.0; // radii (a = b for a circle)
};

Carrier carrierOf(const BezierCurve& piece, double size)
{
  Carrier c;
  const double eps = 1e-10 * size;
  if (piece.degree() == 1)
  {
    c.kind = Carrier::Line;
    return c;
  }
  if (piece.degree() != 2)
  {
    return c;
  }
  const BezierCurve q = piece.inStandardForm();
  const double w = q.weight(1);
  if (!(w < 1.0 - 1e-12))
  {
    return c; // parabola or hyperbola: no such native edge here
  }
  const Vec3 p0 = q.controlPoint(0), p1 = q.controlPoint(1), p2 = q.controlPoint(2);
  const Vec3 o = (0.5 * (p0 + p2) - w * w * p1) / (1.0 - w * w);
  // The conic x^T A x = 1 about o through p0, the shoulder point and p2.
  const Vec3 s = q.evaluate(0.5);
  Eigen::Matrix3d m;
  for (int k = 0; k < 3; ++k)
  {
    const Vec3 d = (k == 0 ? p0 : k == 1 ? s : p2) - o;
    m.row(k) << d.x() * d.x(), d.x() * d.y(), d.y() * d.y();
  }
  const Eigen::Vector3d abc = m.colPivHouseholderQr().solve(Eigen::Vector3d::Ones());
  Eigen::Matrix2d form;
  form << abc(0), 0.5 * abc(1), 0.5 * abc(1), abc(2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(form);
  if (!(eig.eigenvalues()(0) > 0.0))
  {
    return c;
  }
  c.centre = gp_Pnt2d(o.x(), o.y());
  c.a = 1.0 / std::sqrt(eig.eigenvalues()(0));
  c.b = 1.0 / std::sqrt(eig.eigenvalues()(1));
  c.major = gp_Dir2d(eig.eigenvectors()(0, 0), eig.eigenvectors()(1, 0));
  c.kind = std::abs(c.a - c.b) <= eps ? Carrier::Circle : Carrier::Ellipse;
  return c;
}

bool sameCarrier(const Carrier& x, const Carrier& y, const BezierCurve& cx, const BezierCurve& cy, double size)
{
  const double eps = 1e-9 * size;
  if (x.kind != y.kind || x.kind == Carrier::Free)
  {
    return false;
  }
  if (x.kind == Carrier::Line)
  {
    const Vec3 d = cx.endPoint() - cx.startPoint(), e = cy.endPoint() - cy.startPoint();
    return std::abs(d.x() * e.y() - d.y() * e.x()) <= eps * e.norm() && d.dot(e) > 0.0;
  }
  return x.centre.Distance(y.centre) <= eps && std::abs(x.a - y.a) <= eps && std::abs(x.b - y.b) <= eps &&
    (x.kind == Carrier::Circle || std::abs(x.major.Crossed(y.major)) <= 1e-9);
}

gp_Pnt pnt(const Vec3& p)
{
  return gp_Pnt(p.x(), p.y(), 0.0);
}

TopoDS_Edge bezierEdge(const BezierCurve& c)
{
  TColgp_Array1OfPnt poles(1, c.degree() + 1);
  TColStd_Array1OfReal weights(1, c.degree() + 1);
  for (int i = 0; i <= c.degree(); ++i)
  {
    poles.SetValue(i + 1, pnt(c.controlPoint(i)));
    weights.SetValue(i + 1, c.weight(i));
  }
  Handle(Geom_BezierCurve) curve = new Geom_BezierCurve(poles, weights);
  return BRepBuilderAPI_MakeEdge(curve).Edge();
}

// The loop with native edges: runs of pieces on one carrier become one edge.
TopoDS_Wire nativeWire(const Boundary2D& b, const Loop2D& loop)
{
  const int n = static_cast<int>(loop.edges.size());
  const double size = b.diagonal();
  std::vector<Carrier> carriers;
  std::vector<const BezierCurve*> curves;
  for (int e : loop.edges)
  {
    curves.push_back(&b.edges()[e].curve);
    carriers.push_back(carrierOf(*curves.back(), size));
  }
  auto joins = [&](int i, int j) { return sameCarrier(carriers[i], carriers[j], *curves[i], *curves[j], size); };
  // Start where a run starts (or anywhere when the whole loop is one run).
  int start = 0;
  while (start < n && joins((start + n - 1) % n, start))
    ++start;
  // A whole circle or ellipse as one closed edge crashes BRepMAT2d_BisectingLocus (7.6):
  // it gets two half arcs, still native.
  const bool whole = start == n;
  if (whole)
    start = 0;
  const int longest = whole ? (n + 1) / 2 : n;
  BRepBuilderAPI_MakeWire wire;
  for (int k = 0; k < n;)
  {
    const int first = (start + k) % n;
    int count = 1;
    while (k + count < n && count < longest && joins((start + k + count - 1) % n, (start + k + count) % n))
      ++count;
    const int last = (start + k + count - 1) % n;
    const Carrier& c = carriers[first];
    const Vec3 p0 = curves[first]->startPoint(), p1 = curves[last]->endPoint();
    // A point inside the run, on the carrier, that fixes the arc's side.
    const Vec3 mid = count > 1 ? curves[first]->endPoint() : curves[first]->evaluate(0.5);
    const double turn = (mid - p0).x() * (p1 - mid).y() - (mid - p0).y() * (p1 - mid).x();
    const gp_Dir axis = turn > 0.0 ? gp_Dir(0, 0, 1) : gp_Dir(0, 0, -1);
    if (c.kind == Carrier::Line)
      wire.Add(BRepBuilderAPI_MakeEdge(pnt(p0), pnt(p1)).Edge());
    else if (c.kind == Carrier::Circle)
    {
      wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(pnt(p0), pnt(mid), pnt(p1)).Value()).Edge());
    }
    else if (c.kind == Carrier::Ellipse)
    {
      const gp_Elips ellipse(gp_Ax2(gp_Pnt(c.centre.X(), c.centre.Y(), 0.0), axis,
                               gp_Dir(c.major.X(), c.major.Y(), 0.0)), c.a, c.b);
      wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfEllipse(ellipse, pnt(p0), pnt(p1), true).Value()).Edge());
    }
    else
      for (int j = 0; j < count; ++j)
        wire.Add(bezierEdge(*curves[(first + j) % n]));
    k += count;
  }
  return wire.Wire();
}

TopoDS_Wire occtWire(const Boundary2D& b, const Loop2D& loop)
{
  BRepBuilderAPI_MakeWire wire;
  for (int e : loop.edges)
  {
    const BezierCurve& c = b.edges()[e].curve;
    TColgp_Array1OfPnt poles(1, c.degree() + 1);
    TColStd_Array1OfReal weights(1, c.degree() + 1);
    for (int i = 0; i <= c.degree(); ++i)
    {
      const Vec3 p = c.controlPoint(i);
      poles.SetValue(i + 1, gp_Pnt(p.x(), p.y(), 0.0));
      weights.SetValue(i + 1, c.weight(i));
    }
    Handle(Geom_BezierCurve) curve = new Geom_BezierCurve(poles, weights);
    wire.Add(BRepBuilderAPI_MakeEdge(curve).Edge());
  }
  return wire.Wire();
}

TopoDS_Face occtFace(const Boundary2D& b, bool native)
{
  // Outer loop first, then the holes (already clockwise, as a face wants them).
  const Loop2D* outer = nullptr;
  for (const Loop2D& l : b.loops())
    if (l.outer)
      outer = &l;
  auto wireOf = [&](const Loop2D& l) { return native ? nativeWire(b, l) : occtWire(b, l); };
  BRepBuilderAPI_MakeFace face(gp_Pln(), wireOf(*outer));
  for (const Loop2D& l : b.loops())
    if (!l.outer)
      face.Add(wireOf(l));
  return face.Face();
}

// Best time of OpenCASCADE's bisecting locus on the face, with its arc count; "" when it
// fails (the reason in `why`).
double occtMs(const TopoDS_Face& face, int repeats, int& arcs, std::string& why)
{
  try
  {
    bool done = false;
    const double ms = bestMs(repeats, [&] {
      BRepMAT2d_Explorer explorer(face);
      BRepMAT2d_BisectingLocus locus;
      locus.Compute(explorer, 1, MAT_Left);
      done = locus.IsDone();
      arcs = done ? locus.Graph()->NumberOfArcs() : 0;
    });
    if (!done)
      why = "not done";
    return done ? ms : -1.0;
  }
  catch (const Standard_Failure& e)
  {
    why = std::string("exception: ") + e.GetMessageString();
    return -1.0;
  }
}

// Polygons of issue 14's table: a gear of n corners (alternating radii 1 and 0.85 every two
// corners) and a slot 4 x 0.02.
std::vector<NurbsCurve> gear(int n)
{
  Vec3List corners;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2.0 * M_PI * i / n, r = (i / 2) % 2 ? 0.85 : 1.0;
    corners.push_back(Vec3(r * std::cos(a), r * std::sin(a), 0.0));
  }
  return makePolygon(corners);
}

// ExactMAT as OpenCASCADE is timed: from the curves (its explorer reads the face) to the
// MAT — the boundary (loops, orientation, crossing check), the generators and their tree,
// the tracing; best of `repeats`. `error`: the verified error of the MAT.
double exactmatMs(const std::vector<CurvePiece>& pieces, int repeats, double& error)
{
  const double ms = bestMs(repeats, [&] {
    const Boundary2D bb = Boundary2D::build(pieces);
    const Generators gg(bb);
    const MedialGraph graph = computeMAT2D(gg);
  });
  const Boundary2D b = Boundary2D::build(pieces);
  const Generators g(b);
  error = verifyMAT2D(g, computeMAT2D(g)).maxDistanceError;
  return ms;
}

// A closed uniform B-spline (the wavy strip: its last `degree` control points repeat its
// first ones) as OpenCASCADE's native periodic B-spline, the same curve, given as two
// edges (one closed edge is what crashes BRepMAT2d_BisectingLocus on a whole circle).
TopoDS_Face nativeBSplineFace(const NurbsCurve& c)
{
  const int p = c.degree(), poles = c.controlPointCount() - p;
  TColgp_Array1OfPnt points(1, poles);
  for (int i = 0; i < poles; ++i)
    points.SetValue(i + 1, pnt(c.controlPoint(i)));
  TColStd_Array1OfReal knots(1, poles + 1);
  TColStd_Array1OfInteger mults(1, poles + 1);
  for (int i = 0; i <= poles; ++i)
  {
    knots.SetValue(i + 1, c.domainStart() + i);
    mults.SetValue(i + 1, 1);
  }
  Handle(Geom_BSplineCurve) curve = new Geom_BSplineCurve(points, knots, mults, p, true);
  const double t0 = c.domainStart(), t1 = c.domainEnd(), tm = std::floor(0.5 * (t0 + t1));
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(curve, t0, tm).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(curve, tm, t1).Edge());
  return BRepBuilderAPI_MakeFace(gp_Pln(), wire.Wire()).Face();
}

} // namespace

int main(int argc, char* argv[])
{
  // --no-scaling: the catalogue and issue 14's polygons only (the scaling rows run
  // OpenCASCADE on up to 10,000 edges, a few minutes).
  const bool scaling = !(argc > 1 && std::strcmp(argv[1], "--no-scaling") == 0);
  const int repeats = 21;
  std::printf("## ExactMAT vs OpenCASCADE 7.6 BRepMAT2d_BisectingLocus (best of %d runs)\n\n", repeats);
  std::printf("| shape | ExactMAT adaptive 1e-4, set-up + tracing (ms) | verified error | OCCT, native edges (ms) | OCCT arcs | "
              "ratio OCCT / ExactMAT | OCCT, Bézier pieces (ms) |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  std::vector<std::pair<std::string, std::vector<NurbsCurve>>> shapes;
  for (const std::string& name : catalogueNames())
  {
    const Shape s = makeShape(name);
    if (s.dimension == 2)
      shapes.push_back({ name, s.curves });
  }
  shapes.push_back({ "slot 4 x 0.02", makePolygon({ Vec3(-2, -0.01, 0), Vec3(2, -0.01, 0), Vec3(2, 0.01, 0), Vec3(-2, 0.01, 0) }) });
  shapes.push_back({ "gear, 160 edges", gear(160) });
  shapes.push_back({ "gear, 1000 edges", gear(1000) });
  for (const auto& [name, curves] : shapes)
  {
    const std::vector<CurvePiece> pieces = curvePieces(curves);
    const Boundary2D b = Boundary2D::build(pieces);
    double error = 0.0;
    const double ours = exactmatMs(pieces, repeats, error);
    int arcs = 0, bezierArcs = 0;
    std::string why, bezierWhy;
    const double native = occtMs(occtFace(b, true), repeats, arcs, why);
    const double bezier = occtMs(occtFace(b, false), repeats, bezierArcs, bezierWhy);
    char nativeText[64], ratio[32], bezierText[64];
    std::snprintf(nativeText, sizeof nativeText, "%.3f", native);
    std::snprintf(ratio, sizeof ratio, "%.2f", native / ours);
    std::snprintf(bezierText, sizeof bezierText, "%.3f", bezier);
    std::printf("| %s | %.3f | %.1e | %s | %s | %s | %s |\n", name.c_str(), ours, error,
      native >= 0 ? nativeText : why.c_str(), native >= 0 ? std::to_string(arcs).c_str() : "-",
      native >= 0 ? ratio : "-", bezier >= 0 ? bezierText : bezierWhy.c_str());
    std::fflush(stdout);
  }
  if (!scaling)
    return 0;

  // Scaling with the number of boundary entities, both tools on their native input:
  // polygons as lines, the wavy strip's closed cubic B-spline as one periodic B-spline
  // (in two edges) for OpenCASCADE, its Bézier spans for ExactMAT.
  std::printf("\n## Scaling with the number of boundary entities, ExactMAT vs OpenCASCADE (native input, best of 3)\n\n");
  std::printf("| boundary | entities | ExactMAT (ms) | exponent | verified error | OCCT (ms) | exponent | OCCT arcs | ratio OCCT / ExactMAT |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int family = 0; family < 3; ++family)
  {
    double lastOurs = 0.0, lastOcct = 0.0, lastN = 0.0;
    for (const int n : { 100, 1000, 10000 })
    {
      std::vector<NurbsCurve> curves = family == 0 ? makeSawToothStrip(n)
        : family == 1                              ? gear(n)
                                                   : std::vector<NurbsCurve>{ makeWavyStrip(n) };
      const std::vector<CurvePiece> pieces = curvePieces(curves);
      const Boundary2D b = Boundary2D::build(pieces);
      double error = 0.0;
      const double ours = exactmatMs(pieces, 3, error);
      int arcs = 0;
      std::string why;
      const double occt = occtMs(family == 2 ? nativeBSplineFace(curves.front()) : occtFace(b, true), 3, arcs, why);
      auto exponent = [&](double ms, double last) {
        return last > 0.0 && ms > 0.0 ? std::to_string(std::log(ms / last) / std::log(n / lastN)).substr(0, 4) : std::string();
      };
      char occtText[64], ratio[32];
      std::snprintf(occtText, sizeof occtText, "%.1f", occt);
      std::snprintf(ratio, sizeof ratio, "%.2f", occt / ours);
      std::printf("| %s | %zu | %.1f | %s | %.1e | %s | %s | %s | %s |\n",
        family == 0 ? "saw-tooth strip (polygon)" : family == 1 ? "gear (polygon)" : "wavy strip (cubic B-spline)",
        b.edges().size(), ours, exponent(ours, lastOurs).c_str(), error, occt >= 0 ? occtText : why.c_str(),
        occt >= 0 ? exponent(occt, lastOcct).c_str() : "-", occt >= 0 ? std::to_string(arcs).c_str() : "-",
        occt >= 0 ? ratio : "-");
      std::fflush(stdout);
      lastOurs = ours;
      lastOcct = occt;
      lastN = n;
    }
  }
  return 0;
}
