// The peer: OpenCASCADE's 2D bisecting locus (BRepMAT2d_BisectingLocus) on the same
// catalogue shapes, built from the same rational Bézier pieces, timed the same way as
// ExactMAT (best of several runs of the computation alone). Prints a Markdown table.
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"
#include "shapes/Catalogue.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepMAT2d_BisectingLocus.hxx>
#include <BRepMAT2d_Explorer.hxx>
#include <Geom_BezierCurve.hxx>
#include <MAT_Graph.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include <chrono>
#include <cstdio>
#include <string>

using namespace exactmat;

namespace
{
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

TopoDS_Face occtFace(const Boundary2D& b)
{
  // Outer loop first, then the holes (already clockwise, as a face wants them).
  const Loop2D* outer = nullptr;
  for (const Loop2D& l : b.loops())
    if (l.outer)
      outer = &l;
  BRepBuilderAPI_MakeFace face(gp_Pln(), occtWire(b, *outer));
  for (const Loop2D& l : b.loops())
    if (!l.outer)
      face.Add(occtWire(b, l));
  return face.Face();
}

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
} // namespace

int main()
{
  const int repeats = 5;
  std::printf("## ExactMAT vs OpenCASCADE 7.6 BRepMAT2d_BisectingLocus (best of %d runs)\n\n", repeats);
  std::printf("| shape | ExactMAT adaptive 1e-4 (ms) | verified error | OCCT (ms) | OCCT arcs | ratio OCCT / ExactMAT |\n");
  std::printf("|---|---:|---:|---:|---:|---:|\n");
  for (const std::string& name : catalogueNames())
  {
    const Shape s = makeShape(name);
    if (s.dimension != 2)
      continue;
    const Boundary2D b = Boundary2D::build(curvePieces(s.curves));
    const Generators g(b);
    MedialGraph graph;
    const double ours = bestMs(repeats, [&] { graph = computeMAT2D(g); });
    const double error = verifyMAT2D(g, graph).maxDistanceError;
    std::string occt = "failed", arcs = "-", ratio = "-";
    try
    {
      const TopoDS_Face face = occtFace(b);
      int count = 0;
      bool done = false;
      const double ms = bestMs(repeats, [&] {
        BRepMAT2d_Explorer explorer(face);
        BRepMAT2d_BisectingLocus locus;
        locus.Compute(explorer, 1, MAT_Left);
        done = locus.IsDone();
        count = done ? locus.Graph()->NumberOfArcs() : 0;
      });
      if (done)
      {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.2f", ms);
        occt = buf;
        arcs = std::to_string(count);
        std::snprintf(buf, sizeof buf, "%.1f", ms / ours);
        ratio = buf;
      }
      else
        occt = "not done";
    }
    catch (const Standard_Failure& e)
    {
      occt = std::string("exception: ") + e.GetMessageString();
    }
    std::printf("| %s | %.2f | %.1e | %s | %s | %s |\n", name.c_str(), ours, error, occt.c_str(), arcs.c_str(),
      ratio.c_str());
    std::fflush(stdout);
  }
  return 0;
}
