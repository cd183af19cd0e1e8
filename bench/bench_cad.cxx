// Benchmark of exact STEP reading (not a test): per part, the faces and Bézier cells
// vtkCADBoundaryReader makes and its time, beside OpenCASCADE's own reading of the same file
// into its B-rep (the floor: our reader runs it first) and OpenCASCADE's tessellation of that
// B-rep to 1e-4 of the size (what a tessellating reader adds instead of the exact
// conversion); the largest distance of the cells from OpenCASCADE's surfaces. Then scaling:
// plates with k × k round holes.
//
//   exactmat_bench_cad [--quick]
#include "vtkCADBoundaryReader.h"
#include "vtkMATBoundaryConversion.h"

#include "OCCTTestParts.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
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

int main(int argc, char* argv[])
{
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  // Refusals are reported in the table, not as VTK's multi-line log.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
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
