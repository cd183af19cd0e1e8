// Benchmark of exact STEP reading (not a test): per part, the faces and Bézier cells
// vtkCADBoundaryReader makes and its time, beside OpenCASCADE's own reading of the same file
// into its B-rep (the floor: our reader runs it first) and OpenCASCADE's tessellation of that
// B-rep to 1e-4 of the size (what a tessellating reader adds instead of the exact
// conversion); the largest distance of the cells from OpenCASCADE's surfaces. Then scaling:
// plates with k × k round holes.
//
//   exactmat_bench_cad [--quick]
//
// With --fillets N [SEED]: N random boxes with random edges filleted, the same way.
// With --mat: parts as OpenCASCADE makes them (primitives, booleans), written to STEP, read
// exactly and put through vtkMAT3DFilter and vtkSheetInterpolator, as `exactmat 3d` does:
// per part complete (verified, every sheet filled, every face covered), flagged (the
// verification fails: exit 3) or refused (an error naming what is not supported), with the
// counts, the verified error, the coverage and the time.
#include "vtkCADBoundaryReader.h"
#include "vtkMAT3DFilter.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkSheetInterpolator.h"

#include "OCCTTestParts.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <Standard_Failure.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeWedge.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>

#include <vtkCommand.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace
{

double msSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

double fastest(int repeats, const std::function<void()>& work)
{
  double best = HUGE_VAL;
  for (int r = 0; r < repeats; ++r)
  {
    const auto t0 = std::chrono::steady_clock::now();
    work();
    best = std::min(best, msSince(t0));
  }
  return best;
}

class Silent : public vtkCommand
{
public:
  static Silent* New() { return new Silent; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    Message = data ? static_cast<const char*>(data) : "error";
  }
  std::string Message;
};


// A 4k × 4k × 0.5 plate with k × k round through holes, its four vertical edges rounded.
TopoDS_Shape holePlate(int k)
{
  TopoDS_Shape plate = BRepPrimAPI_MakeBox(4.0 * k, 4.0 * k, 0.5).Shape();
  TopoDS_Compound tools;
  BRep_Builder builder;
  builder.MakeCompound(tools);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      builder.Add(tools, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(4.0 * i + 2, 4.0 * j + 2, -1), gp_Dir(0, 0, 1)),
                           0.6 + 0.1 * ((i + j) % 3), 3).Shape());
  plate = BRepAlgoAPI_Cut(plate, tools).Shape();
  BRepFilletAPI_MakeFillet fillet(plate);
  for (TopExp_Explorer ex(plate, TopAbs_EDGE); ex.More(); ex.Next())
  {
    const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
    const gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(e)), b = BRep_Tool::Pnt(TopExp::LastVertex(e));
    const bool vertical = std::abs(a.X() - b.X()) < 1e-9 && std::abs(a.Y() - b.Y()) < 1e-9;
    const bool corner = (a.X() < 1e-9 || a.X() > 4.0 * k - 1e-9) && (a.Y() < 1e-9 || a.Y() > 4.0 * k - 1e-9);
    if (vertical && corner)
      fillet.Add(0.5, e);
  }
  return fillet.Shape();
}

double worstDistance(vtkUnstructuredGrid* grid, const TopoDS_Shape& shape)
{
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worst = 0.0;
  for (const exactmat::PatchPiece& piece : exactmat::patchPiecesFromGrid(grid))
  {
    Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(faces(piece.entity + 1)));
    for (int k = 0; k < 8; ++k)
    {
      double u = uniform(rng), v = uniform(rng);
      if (piece.triangle && u + v > 1.0)
      {
        u = 1.0 - u;
        v = 1.0 - v;
      }
      const exactmat::Vec3 p = piece.patch.evaluate(u, v);
      GeomAPI_ProjectPointOnSurf projection(gp_Pnt(p.x(), p.y(), p.z()), s);
      if (projection.NbPoints() > 0)
        worst = std::max(worst, projection.LowerDistance());
    }
  }
  return worst;
}

void row(const std::string& name, const TopoDS_Shape& shape, int repeats)
{
  const std::string file = "/tmp/exactmat-bench-" + name + ".step";
  {
    STEPControl_Writer writer;
    writer.Transfer(shape, STEPControl_AsIs);
    writer.Write(file.c_str());
  }
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  const double size = std::sqrt(box.SquareExtent());
  TopoDS_Shape native;
  const double occt = fastest(repeats, [&] {
    STEPControl_Reader reader;
    reader.ReadFile(file.c_str());
    reader.TransferRoots();
    native = reader.OneShape();
  });
  const double mesh = fastest(repeats, [&] {
    BRepTools::Clean(native);
    BRepMesh_IncrementalMesh(native, 1e-4 * size, false, 0.5, false);
  });
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  std::string error;
  const double ours = fastest(repeats, [&] {
    vtkNew<vtkCADBoundaryReader> reader;
    vtkNew<Silent> silent;
    reader->AddObserver(vtkCommand::ErrorEvent, silent);
    reader->SetFileName(file.c_str());
    reader->Update();
    grid = reader->GetOutput();
    error = silent->Message;
  });
  int faces = 0;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next())
    ++faces;
  if (!error.empty())
  {
    const size_t colon = error.find(".step: ");
    std::printf("| %s | %d | refused: %s | | %.2f | %.2f | |\n", name.c_str(), faces,
      colon == std::string::npos ? error.c_str() : error.substr(colon + 7, 90).c_str(), occt, mesh);
    return;
  }
  std::printf("| %s | %d | %lld | %.2f | %.2f | %.2f | %.1e |\n", name.c_str(), faces,
    static_cast<long long>(grid->GetNumberOfCells()), ours, occt, mesh, worstDistance(grid, native) / size);
}

} // namespace

// One part through the 3D MAT and its sheets (the `--mat` table's row): 'c' complete,
// 'f' flagged, 'r' refused.
char matRow(const std::string& name, const TopoDS_Shape& shape)
{
  std::string stem = name;
  for (char& c : stem)
    c = std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  const std::string file = "/tmp/exactmat-bench-mat-" + stem + ".step";
  {
    STEPControl_Writer writer;
    writer.Transfer(shape, STEPControl_AsIs);
    writer.Write(file.c_str());
  }
  vtkNew<vtkCADBoundaryReader> reader;
  reader->SetFileName(file.c_str());
  vtkNew<vtkMAT3DFilter> mat;
  mat->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkSheetInterpolator> sheets;
  sheets->SetInputConnection(mat->GetOutputPort());
  sheets->SetSourceConnection(reader->GetOutputPort());
  vtkNew<Silent> silent;
  for (vtkAlgorithm* a : { static_cast<vtkAlgorithm*>(reader), static_cast<vtkAlgorithm*>(mat),
         static_cast<vtkAlgorithm*>(sheets) })
    a->AddObserver(vtkCommand::ErrorEvent, silent);
  const auto start = std::chrono::steady_clock::now();
  sheets->Update();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int faces = 0;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next())
    ++faces;
  if (!silent->Message.empty())
  {
    // (VTK's message after its "ERROR: In file, line N / class (address): " prefix.)
    std::string why = silent->Message;
    if (const size_t at = why.find("): "); at != std::string::npos)
      why = why.substr(at + 3);
    std::replace(why.begin(), why.end(), '\n', ' ');
    std::replace(why.begin(), why.end(), '|', '/');
    std::printf("| %s | %d | refused: %s | | | | | | | %.2f |\n", name.c_str(), faces, why.substr(0, 110).c_str(),
      seconds);
    return 'r';
  }
  const bool complete = mat->GetVerificationPassed() && sheets->GetVerificationPassed();
  std::printf("| %s | %d | %s | %d | %d | %d | %d / %d | %.1e | %.1e | %.2f |\n", name.c_str(), faces,
    complete ? "complete" : "flagged", mat->GetNumberOfJunctions(), mat->GetNumberOfSeams(),
    mat->GetNumberOfCentreCurves() + mat->GetNumberOfSphereCentres(), sheets->GetNumberOfInterpolatedSheets(),
    sheets->GetNumberOfFailedSheets(), std::max(mat->GetMaximumVerifiedError(), sheets->GetMaximumVerifiedError()),
    sheets->GetMaximumCoverageShortfall(), seconds);
  return complete ? 'c' : 'f';
}

// Random filleted boxes (--fillets N [SEED]): sides in [1, 4], a random subset of the 12
// edges rounded with one radius in [0.05, 0.45] x the shortest side (a part OpenCASCADE
// cannot fillet is drawn again), each through matRow; then the tally.
int filletTable(int count, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> side(1.0, 4.0), share(0.05, 0.45), coin(0.0, 1.0);
  std::printf("Random filleted boxes (seed %u) through STEP, vtkMAT3DFilter and vtkSheetInterpolator.\n\n"
              "| part | faces | result | junctions | seams | centre curves, ball centres | sheets filled / failed | "
              "verified error | coverage shortfall | time (s) |\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|\n",
    seed);
  int complete = 0, flagged = 0, refused = 0;
  for (int n = 0, draws = 0; n < count && draws < 10 * count; ++draws)
  {
    const double a = side(random), b = side(random), c = side(random);
    const double radius = share(random) * std::min({ a, b, c });
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(a, b, c).Shape();
    std::vector<TopoDS_Edge> edges;
    for (TopExp_Explorer ex(box, TopAbs_EDGE); ex.More(); ex.Next())
      if (std::none_of(edges.begin(), edges.end(), [&](const TopoDS_Edge& e) { return e.IsSame(ex.Current()); }))
        edges.push_back(TopoDS::Edge(ex.Current()));
    const double p = coin(random);
    std::string which;
    TopoDS_Shape part;
    try
    {
      BRepFilletAPI_MakeFillet fillet(box);
      for (size_t k = 0; k < edges.size(); ++k)
        if (coin(random) < p)
        {
          fillet.Add(radius, edges[k]);
          which += (which.empty() ? "" : ",") + std::to_string(k);
        }
      if (which.empty())
        continue;
      fillet.Build();
      if (!fillet.IsDone())
        continue;
      part = fillet.Shape();
    }
    catch (const Standard_Failure&)
    {
      continue;
    }
    char name[160];
    std::snprintf(name, sizeof name, "%.2f x %.2f x %.2f, edges %s, r %.3f", a, b, c, which.c_str(), radius);
    const char result = matRow(name, part);
    (result == 'c' ? complete : result == 'f' ? flagged : refused) += 1;
    ++n;
  }
  std::printf("\n%d complete, %d flagged, %d refused\n", complete, flagged, refused);
  return 0;
}

int matTable()
{
  std::printf("Parts made by OpenCASCADE, through STEP, vtkMAT3DFilter and vtkSheetInterpolator (one run each).\n\n"
              "| part | faces | result | junctions | seams | centre curves, ball centres | sheets filled / failed | "
              "verified error | coverage shortfall | time (s) |\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|\n");
  matRow("box", BRepPrimAPI_MakeBox(4, 3, 2).Shape());
  matRow("cube", BRepPrimAPI_MakeBox(1, 1, 1).Shape());
  matRow("wedge", BRepPrimAPI_MakeWedge(3, 2, 1, 1).Shape());
  {
    BRepBuilderAPI_MakePolygon hex;
    for (int k = 0; k < 6; ++k)
      hex.Add(gp_Pnt(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0));
    hex.Close();
    matRow("hexagonal prism", BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(hex.Wire()).Face(), gp_Vec(0, 0, 3)).Shape());
  }
  {
    BRepBuilderAPI_MakePolygon l;
    for (const auto& p : { gp_Pnt(0, 0, 0), gp_Pnt(3, 0, 0), gp_Pnt(3, 1, 0), gp_Pnt(1, 1, 0), gp_Pnt(1, 2, 0),
           gp_Pnt(0, 2, 0) })
      l.Add(p);
    l.Close();
    matRow("L prism, square legs", BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(l.Wire()).Face(), gp_Vec(0, 0, 1)).Shape());
  }
  matRow("box with a pocket", BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(4, 3, 2).Shape(),
                                BRepPrimAPI_MakeBox(gp_Pnt(1, 1, 1), 2, 1, 2).Shape()).Shape());
  matRow("plate with a hole", BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(4, 3, 0.5).Shape(),
                                BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(1, 1.5, -1), gp_Dir(0, 0, 1)), 0.5, 3).Shape())
                                .Shape());
  matRow("cylinder r 1, length 4", BRepPrimAPI_MakeCylinder(1, 4).Shape());
  matRow("cylinder r 1, length 2 (= diameter)", BRepPrimAPI_MakeCylinder(1, 2).Shape());
  matRow("cylinder r 2, length 1", BRepPrimAPI_MakeCylinder(2, 1).Shape());
  matRow("half cylinder", BRepPrimAPI_MakeCylinder(1, 2, M_PI).Shape());
  matRow("tube 2 / 1, length 3", BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(2, 3).Shape(),
                                   BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -1), gp_Dir(0, 0, 1)), 1, 5).Shape())
                                   .Shape());
  matRow("cone frustum", BRepPrimAPI_MakeCone(1.0, 0.4, 4.0).Shape());
  matRow("cone with apex", BRepPrimAPI_MakeCone(1.0, 0.0, 3.0).Shape());
  matRow("sphere", BRepPrimAPI_MakeSphere(gp_Pnt(0.5, 0, 0), 1.5).Shape());
  matRow("hemisphere", BRepAlgoAPI_Cut(BRepPrimAPI_MakeSphere(1.0).Shape(),
                         BRepPrimAPI_MakeBox(gp_Pnt(-2, -2, -2), 4, 4, 2).Shape()).Shape());
  {
    TopoDS_Shape capsule = BRepAlgoAPI_Fuse(BRepPrimAPI_MakeCylinder(1, 4).Shape(),
      BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 4), 1).Shape()).Shape();
    matRow("cylinder, one hemispherical end", capsule);
    matRow("capsule", BRepAlgoAPI_Fuse(capsule, BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), 1).Shape()).Shape());
  }
  matRow("torus", BRepPrimAPI_MakeTorus(2, 0.5).Shape());
  matRow("box with a cylindrical boss", BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(4, 4, 1).Shape(),
                                          BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(2, 2, 1), gp_Dir(0, 0, 1)), 0.8, 2).Shape())
                                          .Shape());
  matRow("box with a spherical cavity", BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(4, 3, 2).Shape(),
                                          BRepPrimAPI_MakeSphere(gp_Pnt(2.3, 1.4, 1.1), 0.6).Shape()).Shape());
  {
    TopoDS_Shape box = BRepPrimAPI_MakeBox(4, 2, 3).Shape();
    BRepFilletAPI_MakeFillet fillet(box);
    TopExp_Explorer ex(box, TopAbs_EDGE);
    fillet.Add(0.3, TopoDS::Edge(ex.Current()));
    matRow("box, one edge filleted", fillet.Shape());
  }
  {
    // (Each of a box's edges in turn with a larger fillet: the spine's ends meet the caps at
    // other heights; two opposite edges; every edge, whose corners are blended by spheres.)
    TopoDS_Shape box = BRepPrimAPI_MakeBox(4, 2, 3).Shape();
    std::vector<TopoDS_Edge> edges;
    for (TopExp_Explorer ex(box, TopAbs_EDGE); ex.More(); ex.Next())
      if (std::none_of(edges.begin(), edges.end(), [&](const TopoDS_Edge& e) { return e.IsSame(ex.Current()); }))
        edges.push_back(TopoDS::Edge(ex.Current()));
    for (size_t k : { 1, 4 })
    {
      BRepFilletAPI_MakeFillet fillet(box);
      fillet.Add(0.8, edges[k]);
      matRow("box, edge " + std::to_string(k) + " filleted 0.8", fillet.Shape());
    }
    BRepFilletAPI_MakeFillet two(box);
    two.Add(0.3, edges[0]);
    two.Add(0.5, edges[2]);
    matRow("box, two opposite edges filleted", two.Shape());
    BRepFilletAPI_MakeFillet all(box);
    for (const TopoDS_Edge& e : edges)
      all.Add(0.3, e);
    matRow("box, every edge filleted", all.Shape());
  }
  {
    // (The L prism's reflex edge rounded: a concave fillet, as a bracket's inner corner is.)
    BRepBuilderAPI_MakePolygon l;
    for (const auto& p : { gp_Pnt(0, 0, 0), gp_Pnt(3, 0, 0), gp_Pnt(3, 1, 0), gp_Pnt(1, 1, 0), gp_Pnt(1, 2.5, 0),
           gp_Pnt(0, 2.5, 0) })
      l.Add(p);
    l.Close();
    const TopoDS_Shape prism = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(l.Wire()).Face(), gp_Vec(0, 0, 2)).Shape();
    BRepFilletAPI_MakeFillet inner(prism);
    for (TopExp_Explorer ex(prism, TopAbs_EDGE); ex.More(); ex.Next())
    {
      BRepAdaptor_Curve c(TopoDS::Edge(ex.Current()));
      const gp_Pnt m = c.Value(0.5 * (c.FirstParameter() + c.LastParameter()));
      if (std::abs(m.X() - 1) < 1e-9 && std::abs(m.Y() - 1) < 1e-9)
        inner.Add(0.4, TopoDS::Edge(ex.Current()));
    }
    matRow("L prism, inner edge filleted", inner.Shape());
  }
  {
    // (A fillet between faces that are not perpendicular: the wedge's sloping edge.)
    const TopoDS_Shape wedge = BRepPrimAPI_MakeWedge(3, 2, 1, 1).Shape();
    TopExp_Explorer ex(wedge, TopAbs_EDGE);
    BRepFilletAPI_MakeFillet fillet(wedge);
    fillet.Add(0.2, TopoDS::Edge(ex.Current()));
    matRow("wedge, one edge filleted", fillet.Shape());
  }
  // Cylinders cut off by slanted planes (ruled patches between their sections).
  matRow("box, two fillets meeting at a miter", exactmat::testparts::boxWithMiteredFillets());
  matRow("rod cut at an angle at both ends", exactmat::testparts::rodCutAtAngles());
  matRow("plate with a hole drilled at 20°", exactmat::testparts::plateWithAngledHole(0.35));
  return 0;
}

int main(int argc, char* argv[])
{
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  // Refusals are reported in the table, not as VTK's multi-line log.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  if (argc > 2 && std::strcmp(argv[1], "--fillets") == 0)
  {
    for (Message_SequenceOfPrinters::Iterator it(Message::DefaultMessenger()->Printers()); it.More(); it.Next())
      it.Value()->SetTraceLevel(Message_Fail);
    return filletTable(std::atoi(argv[2]), argc > 3 ? static_cast<unsigned>(std::atoi(argv[3])) : 1u);
  }
  if (argc > 1 && std::strcmp(argv[1], "--mat") == 0)
  {
    for (Message_SequenceOfPrinters::Iterator it(Message::DefaultMessenger()->Printers()); it.More(); it.Next())
      it.Value()->SetTraceLevel(Message_Fail);
    return matTable();
  }
  const int repeats = quick ? 1 : 5;
  for (Message_SequenceOfPrinters::Iterator it(Message::DefaultMessenger()->Printers()); it.More(); it.Next())
    it.Value()->SetTraceLevel(Message_Fail);
  std::printf("Exact STEP reading: vtkCADBoundaryReader (OpenCASCADE's read + exact conversion) beside\n"
              "OpenCASCADE's read alone and its tessellation to 1e-4 of the size; min of %d runs, ms.\n\n",
    repeats);
  std::printf("| part | faces | Bézier cells | ExactMAT read (ms) | OCCT read (ms) | OCCT mesh 1e-4 (ms) | "
              "largest distance / size |\n|---|---:|---:|---:|---:|---:|---:|\n");
  row("box", BRepPrimAPI_MakeBox(4, 2, 3).Shape(), repeats);
  row("cylinder", BRepPrimAPI_MakeCylinder(1, 2).Shape(), repeats);
  row("sphere", BRepPrimAPI_MakeSphere(1).Shape(), repeats);
  row("torus", BRepPrimAPI_MakeTorus(2, 0.5).Shape(), repeats);
  {
    TopoDS_Shape box = BRepPrimAPI_MakeBox(4, 2, 3).Shape();
    BRepFilletAPI_MakeFillet all(box);
    for (TopExp_Explorer ex(box, TopAbs_EDGE); ex.More(); ex.Next())
      all.Add(0.3, TopoDS::Edge(ex.Current()));
    row("box-all-edges-filleted", all.Shape(), repeats);
  }
  row("free-form-extrusion", BRepPrimAPI_MakePrism(exactmat::testparts::waveProfile(), gp_Vec(0, 0, 0.7)).Shape(), repeats);
  row("free-form-revolution", BRepPrimAPI_MakeRevol(exactmat::testparts::waveProfile(), gp_Ax1(gp_Pnt(0, -0.5, 0), gp_Dir(1, 0, 0))).Shape(),
    repeats);
  for (int k : quick ? std::vector<int>{ 1, 2 } : std::vector<int>{ 1, 2, 4, 8, 16 })
    row("plate-" + std::to_string(k) + "x" + std::to_string(k) + "-holes", holePlate(k), repeats);
  return 0;
}
