// vtkCADBoundaryReader: parts written by OpenCASCADE itself in STEP and IGES, read back as
// exact Bézier boundaries and compared with OpenCASCADE's own geometry and mass properties;
// MATs of read parts against the same shapes built here; bad files.
#include "vtkCADBoundaryReader.h"
#include "vtkExactMATArrayNames.h"
#include "vtkMAT25DFilter.h"
#include "vtkMAT2DFilter.h"
#include "vtkMAT3DFilter.h"
#include "vtkNURBSSource.h"
#include "vtkSheetInterpolator.h"

#include "OCCTTestParts.h"
#include "TestHelpers.h"

#include "brep/Boundary3D.h"
#include "medial/MedialComplex.h"
#include "shapes/Catalogue.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepPrimAPI_MakeWedge.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineCurve.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <Quantity_Color.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <csignal>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <random>

using namespace exactmat;

namespace
{

// OpenCASCADE's writers print statistics; the tests want only failures on the terminal.
const bool QuietOpenCASCADE = [] {
  for (Message_SequenceOfPrinters::Iterator it(Message::DefaultMessenger()->Printers()); it.More(); it.Next())
    it.Value()->SetTraceLevel(Message_Fail);
  return true;
}();

std::string output(const std::string& name)
{
  return std::string(EXACTMAT_TEST_OUTPUT) + "/" + name;
}

void writeStep(const TopoDS_Shape& shape, const std::string& file)
{
  STEPControl_Writer writer;
  ASSERT_EQ(writer.Transfer(shape, STEPControl_AsIs), IFSelect_RetDone);
  ASSERT_EQ(writer.Write(file.c_str()), IFSelect_RetDone);
}

void writeIges(const TopoDS_Shape& shape, const std::string& file)
{
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 1); // B-rep mode: solids stay solids
  ASSERT_TRUE(writer.AddShape(shape));
  writer.ComputeModel();
  ASSERT_TRUE(writer.Write(file.c_str()));
}

struct Read
{
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  std::string errors;
  std::string unit;
  int parts = 0;
};

Read readCAD(const std::string& file, int dimension = 0, int part = 0)
{
  vtkNew<vtkCADBoundaryReader> reader;
  reader->SetFileName(file.c_str());
  reader->SetDimension(dimension);
  reader->SetPartIndex(part);
  auto rec = ErrorRecorder::watch(reader);
  reader->Update();
  Read r;
  r.grid = reader->GetOutput();
  r.errors = rec->Messages;
  r.unit = reader->GetLengthUnit() ? reader->GetLengthUnit() : "";
  r.parts = reader->GetNumberOfParts();
  return r;
}

// Gauss–Legendre nodes and weights on [0, 1].
void gauss(int n, std::vector<double>& x, std::vector<double>& w)
{
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i)
  {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it)
    {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k)
      {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16)
        break;
    }
    x[i] = 0.5 * (1.0 - z);
    w[i] = 1.0 / ((1.0 - z * z) * dp * dp);
  }
}

struct Mass
{
  double area = 0.0, volume = 0.0;
};

// Area and enclosed volume of the oriented faces, by 24 × 24 Gauss points per patch.
Mass massOf(const Boundary3D& boundary)
{
  std::vector<double> x, w;
  gauss(24, x, w);
  Mass m;
  for (const Face3D& f : boundary.faces())
  {
    for (size_t i = 0; i < x.size(); ++i)
    {
      for (size_t j = 0; j < x.size(); ++j)
      {
        const SurfaceDerivatives d = f.patch.derivatives(x[i], x[j]);
        const Vec3 n = d.su.cross(d.sv);
        m.area += w[i] * w[j] * n.norm();
        m.volume += w[i] * w[j] * d.point.dot(n) / 3.0;
      }
    }
  }
  return m;
}

// Largest distance from points of the read patches to OpenCASCADE's surface of the face the
// patch says it comes from (FaceId), over about 1,000 random points in all. Without
// `byFaceId` (IGES: the reader sews loose faces, which numbers them anew) the distance is
// to the nearest of the shape's surfaces.
double worstSurfaceDistance(vtkUnstructuredGrid* grid, const TopoDS_Shape& shape, bool byFaceId = true)
{
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  const std::vector<PatchPiece> pieces = patchPiecesFromGrid(grid);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worst = 0.0;
  const int perPatch = std::max(1, 1000 / static_cast<int>(pieces.size()));
  for (const PatchPiece& piece : pieces)
  {
    if (piece.entity < 0 || piece.entity >= faces.Extent())
    {
      return HUGE_VAL;
    }
    std::vector<Handle(Geom_Surface)> surfaces;
    for (int f = 1; f <= faces.Extent(); ++f)
    {
      if (!byFaceId || f == piece.entity + 1)
      {
        surfaces.push_back(BRep_Tool::Surface(TopoDS::Face(faces(f))));
      }
    }
    for (int k = 0; k < perPatch; ++k)
    {
      double u = uniform(rng), v = uniform(rng);
      if (piece.triangle && u + v > 1.0)
      {
        u = 1.0 - u;
        v = 1.0 - v;
      }
      const Vec3 p = piece.patch.evaluate(u, v);
      double nearest = HUGE_VAL;
      for (const Handle(Geom_Surface)& s : surfaces)
      {
        GeomAPI_ProjectPointOnSurf projection(gp_Pnt(p.x(), p.y(), p.z()), s);
        if (projection.NbPoints() > 0)
        {
          double a, b;
          projection.LowerDistanceParameters(a, b);
          const gp_Pnt q = s->Value(a, b);
          nearest = std::min(nearest, (p - Vec3(q.X(), q.Y(), q.Z())).norm());
        }
      }
      worst = std::max(worst, nearest);
    }
  }
  return worst;
}

double diagonalOf(vtkUnstructuredGrid* grid)
{
  double b[6];
  grid->GetBounds(b);
  return std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
}


// Area and volume of the extrusion of exactmat::testparts::waveProfile() by `height`, from exact line integrals
// over the profile's edges (Green: area = ∮ x dy), by Gauss points per knot span.
Mass extrusionMass(double height)
{
  std::vector<double> x, w;
  gauss(40, x, w);
  const TopoDS_Face face = exactmat::testparts::waveProfile();
  double area = 0.0, perimeter = 0.0;
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
  {
    const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
    BRepAdaptor_Curve c(e);
    std::vector<double> breaks{ c.FirstParameter() };
    if (c.GetType() == GeomAbs_BSplineCurve)
    {
      for (int k = 1; k <= c.BSpline()->NbKnots(); ++k)
      {
        const double t = c.BSpline()->Knot(k);
        if (t > breaks.back() && t < c.LastParameter())
          breaks.push_back(t);
      }
    }
    breaks.push_back(c.LastParameter());
    const double sign = e.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
    for (size_t s = 0; s + 1 < breaks.size(); ++s)
    {
      for (size_t i = 0; i < x.size(); ++i)
      {
        const double t = breaks[s] + x[i] * (breaks[s + 1] - breaks[s]);
        gp_Pnt p;
        gp_Vec d;
        c.D1(t, p, d);
        const double dt = w[i] * (breaks[s + 1] - breaks[s]);
        area += sign * p.X() * d.Y() * dt;
        perimeter += d.Magnitude() * dt;
      }
    }
  }
  area = std::abs(area);
  return { 2.0 * area + height * perimeter, area * height };
}

// The catalogue shape's NURBS curves as OpenCASCADE B-spline edges, exactly.
std::vector<TopoDS_Edge> occtEdges(const Shape& shape)
{
  std::vector<TopoDS_Edge> edges;
  for (const NurbsCurve& c : shape.curves)
  {
    TColgp_Array1OfPnt poles(1, c.controlPointCount());
    TColStd_Array1OfReal weights(1, c.controlPointCount());
    for (int i = 0; i < c.controlPointCount(); ++i)
    {
      const Vec3 p = c.controlPoint(i);
      poles(i + 1) = gp_Pnt(p.x(), p.y(), p.z());
      weights(i + 1) = c.weight(i);
    }
    std::vector<double> distinct;
    std::vector<int> mult;
    for (double k : c.knots())
    {
      if (!distinct.empty() && k == distinct.back())
        ++mult.back();
      else
      {
        distinct.push_back(k);
        mult.push_back(1);
      }
    }
    TColStd_Array1OfReal knots(1, static_cast<int>(distinct.size()));
    TColStd_Array1OfInteger mults(1, static_cast<int>(distinct.size()));
    for (size_t i = 0; i < distinct.size(); ++i)
    {
      knots(static_cast<int>(i) + 1) = distinct[i];
      mults(static_cast<int>(i) + 1) = mult[i];
    }
    Handle(Geom_BSplineCurve) b = new Geom_BSplineCurve(poles, weights, knots, mults, c.degree());
    edges.push_back(BRepBuilderAPI_MakeEdge(b));
  }
  return edges;
}

// A file through vtkMAT3DFilter and vtkSheetInterpolator as `exactmat 3d` runs them, the
// filters' error messages recorded.
struct MATPipeline
{
  vtkNew<vtkCADBoundaryReader> reader;
  vtkNew<vtkMAT3DFilter> mat;
  vtkNew<vtkSheetInterpolator> sheets;
  std::string matErrors, sheetErrors;
  explicit MATPipeline(const std::string& file)
  {
    reader->SetFileName(file.c_str());
    mat->SetInputConnection(reader->GetOutputPort());
    sheets->SetInputConnection(mat->GetOutputPort());
    sheets->SetSourceConnection(reader->GetOutputPort());
    auto sheetWatch = ErrorRecorder::watch(sheets);
    auto matWatch = ErrorRecorder::watch(mat);
    sheets->Update();
    matErrors = matWatch->Messages;
    sheetErrors = sheetWatch->Messages;
  }
};

std::map<std::string, TopoDS_Shape> solids()
{
  std::map<std::string, TopoDS_Shape> s;
  s["box"] = BRepPrimAPI_MakeBox(gp_Pnt(1e3, 2e3, -5e2), 4, 2, 3).Shape();
  s["cylinder"] = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(1, 2, 3), gp_Dir(1, 1, 0)), 1, 2).Shape();
  s["cone"] = BRepPrimAPI_MakeCone(1.0, 0.4, 2.0).Shape();
  s["sphere"] = BRepPrimAPI_MakeSphere(gp_Pnt(0.5, 0, 0), 1.5).Shape();
  s["torus"] = BRepPrimAPI_MakeTorus(2, 0.5).Shape();
  {
    TopoDS_Shape box = BRepPrimAPI_MakeBox(4, 2, 3).Shape();
    BRepFilletAPI_MakeFillet fillet(box);
    TopExp_Explorer ex(box, TopAbs_EDGE);
    fillet.Add(0.3, TopoDS::Edge(ex.Current()));
    s["box-one-fillet"] = fillet.Shape();
  }
  {
    // Every edge rounded: cylinders meeting sphere octants at the corners (STEP stores
    // their boundary parameter curves as B-splines; the octants reach the poles).
    TopoDS_Shape box = BRepPrimAPI_MakeBox(4, 2, 3).Shape();
    BRepFilletAPI_MakeFillet fillet(box);
    for (TopExp_Explorer ex(box, TopAbs_EDGE); ex.More(); ex.Next())
      fillet.Add(0.3, TopoDS::Edge(ex.Current()));
    s["box-all-edges-filleted"] = fillet.Shape();
  }
  s["box-mitered-fillets"] = exactmat::testparts::boxWithMiteredFillets();
  s["rod-cut-at-angles"] = exactmat::testparts::rodCutAtAngles();
  {
    // 16 holes of three radii in one face: its polygon has 17 loops (VTK's contour
    // triangulator dropped triangles here; CGAL's constrained triangulation does not).
    TopoDS_Compound holes;
    BRep_Builder builder;
    builder.MakeCompound(holes);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        builder.Add(holes, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(4.0 * i + 2, 4.0 * j + 2, -1), gp_Dir(0, 0, 1)),
                             0.6 + 0.1 * ((i + j) % 3), 3).Shape());
    s["plate-16-holes"] = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(16, 16, 0.5).Shape(), holes).Shape();
  }
  // A spherical cavity off the box's centre: two shells; the cavity's faces must come out
  // with their normals into it (volume = box − ball).
  s["box-with-spherical-cavity"] = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(4, 3, 2).Shape(),
    BRepPrimAPI_MakeSphere(gp_Pnt(2.3, 1.4, 1.1), 0.6).Shape()).Shape();
  s["plate-with-hole"] = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(4, 3, 0.5).Shape(),
    BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(1, 1.5, -1), gp_Dir(0, 0, 1)), 0.5, 3).Shape()).Shape();
  {
    BRepBuilderAPI_MakePolygon l;
    for (const auto& p : { gp_Pnt(0, 0, 0), gp_Pnt(3, 0, 0), gp_Pnt(3, 1, 0), gp_Pnt(1, 1, 0),
           gp_Pnt(1, 2, 0), gp_Pnt(0, 2, 0) })
      l.Add(p);
    l.Close();
    s["l-prism"] = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(l.Wire()).Face(), gp_Vec(0, 0, 1)).Shape();
  }
  s["free-form-extrusion"] = BRepPrimAPI_MakePrism(exactmat::testparts::waveProfile(), gp_Vec(0, 0, 0.7)).Shape();
  s["free-form-revolution"] =
    BRepPrimAPI_MakeRevol(exactmat::testparts::waveProfile(), gp_Ax1(gp_Pnt(0, -0.5, 0), gp_Dir(1, 0, 0))).Shape();
  return s;
}

} // namespace

TEST(vtkCADBoundaryReader, SolidsAgreeWithOpenCASCADE)
{
  for (const auto& [name, shape] : solids())
  {
    GProp_GProps surface, volume;
    // OpenCASCADE's adaptive integration, to a relative error far below the test's.
    BRepGProp::SurfaceProperties(shape, surface, 1e-13);
    BRepGProp::VolumeProperties(shape, volume, 1e-13);
    for (const std::string ext : { ".step", ".igs" })
    {
      SCOPED_TRACE(name + ext);
      const std::string file = output("cad-" + name + ext);
      if (ext == ".step")
        writeStep(shape, file);
      else
        writeIges(shape, file);
      const Read r = readCAD(file);
      if (name == "rod-cut-at-angles" && ext == ".igs")
      {
        // OpenCASCADE's IGES writer stores the slanted ellipses as polynomial B-splines 0.13
        // off the cylinder (edge tolerance 0.14): no exact section to read, and the reader
        // says so.
        EXPECT_NE(r.errors.find("face 0 is a trimmed cylinder"), std::string::npos) << r.errors;
        EXPECT_NE(r.errors.find("off the section of its plane by 0.1"), std::string::npos) << r.errors;
        continue;
      }
      ASSERT_TRUE(r.errors.empty()) << r.errors;
      ASSERT_GT(r.grid->GetNumberOfCells(), 0);
      EXPECT_EQ(r.unit, "MM");
      EXPECT_EQ(r.parts, 1);
      ASSERT_TRUE(gridHasSurfaceCells(r.grid));
      const double size = diagonalOf(r.grid);
      // STEP keeps OpenCASCADE's face order: FaceId names the face. IGES stores surfaces
      // to fewer digits (the cylinder moves by 1e-10) and the reader sews its loose faces
      // anew: each point is measured to the nearest surface OpenCASCADE reads from the file.
      if (ext == ".step")
      {
        EXPECT_LE(worstSurfaceDistance(r.grid, shape), 1e-12 * size);
      }
      else
      {
        IGESControl_Reader own;
        ASSERT_EQ(own.ReadFile(file.c_str()), IFSelect_RetDone);
        own.TransferRoots();
        EXPECT_LE(worstSurfaceDistance(r.grid, own.OneShape(), false), 1e-12 * size);
      }
      // Conforming and closed: the 3D kernel's B-rep accepts it.
      Boundary3D boundary;
      try
      {
        boundary = Boundary3D::build(patchPiecesFromGrid(r.grid));
      }
      catch (const std::exception& e)
      {
        ADD_FAILURE() << e.what();
        continue;
      }
      // OpenCASCADE's own integration misses by ~1e-5 on planar faces trimmed by a
      // B-spline: there the reference is the exact line integral over the profile.
      const Mass exact = name == "free-form-extrusion" ? extrusionMass(0.7)
                                                       : Mass{ surface.Mass(), volume.Mass() };
      const Mass m = massOf(boundary);
      EXPECT_NEAR(m.area, exact.area, 1e-9 * exact.area);
      EXPECT_NEAR(m.volume, exact.volume, 1e-9 * exact.volume);
      vtkStringArray* unit = vtkStringArray::SafeDownCast(r.grid->GetFieldData()->GetAbstractArray("LengthUnit"));
      ASSERT_TRUE(unit);
      EXPECT_EQ(unit->GetValue(0), "MM");
    }
  }
}

TEST(vtkCADBoundaryReader, LengthsStayInTheFilesUnit)
{
  // A 25.4 mm cube written in inches is read as a 1 inch cube, unit INCH.
  STEPControl_Controller::Init(); // defines the writer's settings in a fresh process
  ASSERT_TRUE(Interface_Static::SetCVal("write.step.unit", "INCH"));
  writeStep(BRepPrimAPI_MakeBox(25.4, 25.4, 25.4).Shape(), output("cad-inch.step"));
  Interface_Static::SetCVal("write.step.unit", "MM");
  const Read r = readCAD(output("cad-inch.step"));
  ASSERT_TRUE(r.errors.empty()) << r.errors;
  EXPECT_EQ(r.unit, "INCH");
  double b[6];
  r.grid->GetBounds(b);
  EXPECT_NEAR(b[1] - b[0], 1.0, 1e-12);
  EXPECT_NEAR(b[5] - b[4], 1.0, 1e-12);
  // Reading does not change OpenCASCADE's process-wide unit.
  EXPECT_STREQ(Interface_Static::CVal("xstep.cascade.unit"), "MM");
}

TEST(vtkCADBoundaryReader, BoxMATIsTheCatalogueBoxMAT)
{
  // The same 4 × 3 × 2 box from a STEP file and from vtkNURBSSource: the same junctions.
  writeStep(BRepPrimAPI_MakeBox(gp_Pnt(-2, -1.5, -1), 4, 3, 2).Shape(), output("cad-mat-box.step"));
  vtkNew<vtkCADBoundaryReader> reader;
  reader->SetFileName(output("cad-mat-box.step").c_str());
  vtkNew<vtkNURBSSource> box;
  box->SetShapeName("box");
  box->SetWidth(4.0);
  box->SetHeight(3.0);
  box->SetLength(2.0);
  std::vector<std::vector<double>> junctions[2];
  int seams[2] = { 0, 0 };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkMAT3DFilter> mat;
    mat->SetInputConnection(k == 0 ? reader->GetOutputPort() : box->GetOutputPort());
    auto errors = ErrorRecorder::watch(mat);
    mat->Update();
    ASSERT_TRUE(errors->Messages.empty()) << errors->Messages;
    EXPECT_TRUE(mat->GetVerificationPassed());
    seams[k] = mat->GetNumberOfSeams();
    vtkPolyData* out = mat->GetOutput();
    vtkDataArray* type = out->GetPointData()->GetArray(arrays::PointType);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      if (type->GetTuple1(i) == 2)
      {
        double x[3];
        out->GetPoint(i, x);
        junctions[k].push_back({ std::round(x[0] * 1e9) / 1e9, std::round(x[1] * 1e9) / 1e9,
          std::round(x[2] * 1e9) / 1e9 });
      }
    }
    std::sort(junctions[k].begin(), junctions[k].end());
    junctions[k].erase(std::unique(junctions[k].begin(), junctions[k].end()), junctions[k].end());
  }
  EXPECT_EQ(seams[0], seams[1]);
  EXPECT_EQ(seams[0], 12);
  EXPECT_EQ(junctions[0], junctions[1]);
  EXPECT_EQ(junctions[0].size(), 4u);
  // A clean file: OpenCASCADE's translator found nothing to heal (the array is there, empty).
  EXPECT_EQ(reader->GetNumberOfTranslatorMessages(), 0);
  auto* messages =
    vtkStringArray::SafeDownCast(reader->GetOutput()->GetFieldData()->GetAbstractArray("TranslatorMessages"));
  ASSERT_NE(messages, nullptr);
  EXPECT_EQ(messages->GetNumberOfValues(), 0);
}

TEST(vtkCADBoundaryReader, SphereMATIsItsCentre)
{
  // OpenCASCADE's sphere (radius 1.5 about (0.5, 0, 0)), from STEP and from IGES: its MAT is
  // its centre alone — one SphereCentre vertex of radius 1.5 — and the sheet interpolator,
  // with no sheet to fill, finds every face covered by that one ball.
  const TopoDS_Shape sphere = BRepPrimAPI_MakeSphere(gp_Pnt(0.5, 0, 0), 1.5).Shape();
  for (const std::string ext : { ".step", ".igs" })
  {
    SCOPED_TRACE(ext);
    const std::string file = output("cad-mat-sphere" + ext);
    if (ext == ".step")
      writeStep(sphere, file);
    else
      writeIges(sphere, file);
    const MATPipeline run(file);
    ASSERT_TRUE(run.matErrors.empty()) << run.matErrors;
    ASSERT_TRUE(run.sheetErrors.empty()) << run.sheetErrors;
    vtkMAT3DFilter* mat = run.mat;
    vtkSheetInterpolator* sheets = run.sheets;
    EXPECT_TRUE(mat->GetVerificationPassed());
    EXPECT_EQ(mat->GetNumberOfSphereCentres(), 1);
    EXPECT_EQ(mat->GetNumberOfJunctions(), 0);
    EXPECT_EQ(mat->GetNumberOfSeams(), 0);
    vtkPolyData* out = mat->GetOutput();
    ASSERT_EQ(out->GetNumberOfPoints(), 1);
    ASSERT_EQ(out->GetNumberOfVerts(), 1);
    EXPECT_EQ(out->GetNumberOfCells(), 1);
    double x[3];
    out->GetPoint(0, x);
    EXPECT_NEAR(x[0], 0.5, 1e-12);
    EXPECT_NEAR(x[1], 0.0, 1e-12);
    EXPECT_NEAR(x[2], 0.0, 1e-12);
    EXPECT_NEAR(out->GetPointData()->GetArray(arrays::Radius)->GetTuple1(0), 1.5, 1e-12);
    EXPECT_EQ(out->GetPointData()->GetArray(arrays::PointType)->GetTuple1(0), 7);
    EXPECT_EQ(out->GetCellData()->GetArray(arrays::ElementType)->GetTuple1(0), 8);
    EXPECT_TRUE(sheets->GetVerificationPassed());
    EXPECT_EQ(sheets->GetNumberOfSheets(), 0);
    EXPECT_LE(sheets->GetMaximumCoverageShortfall(), 1e-12);
    EXPECT_EQ(sheets->GetOutput()->GetNumberOfVerts(), 1);
  }
}

TEST(vtkCADBoundaryReader, CanalSolidsAreComplete)
{
  // Shafts as CAD writes them: OpenCASCADE's cylinder and cone about z (each cap a face
  // the reader tiles into patches that meet at its centre, the apex of the cap's cone
  // sheet: the centre curve's end touches every piece there, at one point — until
  // 2026-11-28 that end was not taken as a cap end and the cap sheets failed), and a
  // capsule (a cylinder fused with two balls: its axis ends at the balls' centres, each
  // end ball touching a whole hemisphere); a cone with its apex.
  struct Case
  {
    std::string name;
    TopoDS_Shape shape;
    int sheets;
  };
  TopoDS_Shape capsule = BRepAlgoAPI_Fuse(BRepPrimAPI_MakeCylinder(1, 4).Shape(),
    BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 4), 1).Shape()).Shape();
  capsule = BRepAlgoAPI_Fuse(capsule, BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), 1).Shape()).Shape();
  const std::vector<Case> cases{ { "cylinder", BRepPrimAPI_MakeCylinder(1, 4).Shape(), 2 },
    { "cone", BRepPrimAPI_MakeCone(1.0, 0.4, 4.0).Shape(), 2 }, { "capsule", capsule, 0 },
    // (A cone with its apex: the centre curve's balls shrink into the apex, where every
    // emptiness test of the cone's own face was undecided down to depth 24 along the circle
    // of tangency — the run did not end. The searches are bounded now.)
    { "cone-with-apex", BRepPrimAPI_MakeCone(1.0, 0.0, 3.0).Shape(), 1 },
    // (A rod cut at an angle at both ends: its side ruled patches between ellipses, whose
    // closest points near the axis ran out of boxes, and whose slanted cone sheets refined
    // toward their apexes without end — 2026-11-29.)
    { "rod-cut-at-angles", exactmat::testparts::rodCutAtAngles(), 2 } };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
#ifdef __SANITIZE_ADDRESS__
    if (c.name == "cone-with-apex")
      continue; // (5 s in Release: its searches run to their box limit near the apex)
#endif
    const std::string file = output("cad-canal-" + c.name + ".step");
    writeStep(c.shape, file);
    const MATPipeline run(file);
    ASSERT_TRUE(run.matErrors.empty()) << run.matErrors;
    ASSERT_TRUE(run.sheetErrors.empty()) << run.sheetErrors;
    vtkMAT3DFilter* mat = run.mat;
    vtkSheetInterpolator* sheets = run.sheets;
    EXPECT_TRUE(mat->GetVerificationPassed());
    EXPECT_EQ(mat->GetNumberOfCentreCurves(), 1);
    EXPECT_EQ(mat->GetNumberOfSeams(), 0);
    EXPECT_TRUE(sheets->GetVerificationPassed());
    EXPECT_EQ(sheets->GetNumberOfInterpolatedSheets(), c.sheets);
    EXPECT_EQ(sheets->GetNumberOfFailedSheets(), 0);
    EXPECT_LE(sheets->GetMaximumCoverageShortfall(), 1e-3);
    if (c.name == "capsule")
    {
      // The axis from (0, 0, 0) to (0, 0, 4), radius 1 all along.
      vtkPolyData* out = mat->GetOutput();
      double lowest = INFINITY, highest = -INFINITY;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double x[3];
        out->GetPoint(i, x);
        EXPECT_NEAR(std::hypot(x[0], x[1]), 0.0, 1e-10);
        EXPECT_NEAR(out->GetPointData()->GetArray(arrays::Radius)->GetTuple1(i), 1.0, 1e-10);
        lowest = std::min(lowest, x[2]);
        highest = std::max(highest, x[2]);
      }
      // (The fused file's faces are known to about 1e-12 of its size of 7.5.)
      EXPECT_NEAR(lowest, 0.0, 1e-10);
      EXPECT_NEAR(highest, 4.0, 1e-10);
    }
    if (c.name == "rod-cut-at-angles")
    {
      // The axis (0.3, −0.2, z), radius 1, ends where its ball touches a slanted end: the
      // plane through (0, 0, z0) turned by a about d = (1, 0.2, 0)/|·| has the normal
      // (sin a·d_y, −sin a·d_x, cos a); the ball lies 1 below the upper one, above the lower.
      auto end = [](double a, double z0, double side) {
        const double dx = 1.0 / std::hypot(1.0, 0.2), dy = 0.2 / std::hypot(1.0, 0.2);
        return z0 + (side - std::sin(a) * (0.3 * dy + 0.2 * dx)) / std::cos(a);
      };
      vtkPolyData* out = mat->GetOutput();
      double lowest = INFINITY, highest = -INFINITY;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double x[3];
        out->GetPoint(i, x);
        EXPECT_NEAR(std::hypot(x[0] - 0.3, x[1] + 0.2), 0.0, 1e-10);
        EXPECT_NEAR(out->GetPointData()->GetArray(arrays::Radius)->GetTuple1(i), 1.0, 1e-10);
        lowest = std::min(lowest, x[2]);
        highest = std::max(highest, x[2]);
      }
      EXPECT_NEAR(lowest, end(-0.3, -2.1, 1.0), 1e-9);
      EXPECT_NEAR(highest, end(0.5, 1.8, -1.0), 1e-9);
    }
  }
}

TEST(vtkCADBoundaryReader, AngledHoleIsComplete)
{
  // A plate drilled at an angle (a part's angled bore): the hole's wall is a cylinder cut by
  // the plate's faces along ellipses — refused by the reader until 2026-11-29, read now as
  // ruled patches; its MAT has the straight hole's topology at every tilt.
  for (const double tilt : { 0.0, 0.35, 0.6 })
  {
    SCOPED_TRACE(tilt);
    const std::string file = output("cad-angled-hole-" + std::to_string(tilt) + ".step");
    writeStep(exactmat::testparts::plateWithAngledHole(tilt), file);
    const MATPipeline run(file);
    ASSERT_TRUE(run.matErrors.empty()) << run.matErrors;
    ASSERT_TRUE(run.sheetErrors.empty()) << run.sheetErrors;
    vtkMAT3DFilter* mat = run.mat;
    vtkSheetInterpolator* sheets = run.sheets;
    EXPECT_TRUE(mat->GetVerificationPassed());
    EXPECT_EQ(mat->GetNumberOfTopologyProblems(), 0);
    EXPECT_EQ(mat->GetNumberOfJunctions(), 4);
    EXPECT_EQ(mat->GetNumberOfSeams(), 13);
    EXPECT_TRUE(sheets->GetVerificationPassed());
    EXPECT_EQ(sheets->GetNumberOfFailedSheets(), 0);
    EXPECT_LE(sheets->GetMaximumCoverageShortfall(), 1e-3);
  }
}

TEST(vtkCADBoundaryReader, LPrismWithSquareLegsIsComplete)
{
  // An L prism as tall as its legs are wide (3 × 2, legs 1, height 1): each leg is a square
  // tube, along whose axis the seam is degenerate (four touchpoints) from where the wall
  // opposite begins, at the reflex edge. The seam from the corner cube's junction runs
  // into that wall tangentially; the junction is where the wall begins, not where the step
  // that first saw it ended (a piece border of the tiled cap, 0.111 further: a spurious
  // junction and a doubled seam, flagged, until 2026-11-28). 5 junctions, 15 seams, every
  // sheet filled, every face covered.
  BRepBuilderAPI_MakePolygon l;
  for (const auto& p : { gp_Pnt(0, 0, 0), gp_Pnt(3, 0, 0), gp_Pnt(3, 1, 0), gp_Pnt(1, 1, 0), gp_Pnt(1, 2, 0),
         gp_Pnt(0, 2, 0) })
    l.Add(p);
  l.Close();
  const std::string file = output("cad-square-legs.step");
  writeStep(BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(l.Wire()).Face(), gp_Vec(0, 0, 1)).Shape(), file);
  const MATPipeline run(file);
  ASSERT_TRUE(run.matErrors.empty()) << run.matErrors;
  ASSERT_TRUE(run.sheetErrors.empty()) << run.sheetErrors;
  vtkMAT3DFilter* mat = run.mat;
  vtkSheetInterpolator* sheets = run.sheets;
  EXPECT_TRUE(mat->GetVerificationPassed());
  EXPECT_EQ(mat->GetNumberOfTopologyProblems(), 0);
  EXPECT_EQ(mat->GetNumberOfJunctions(), 5);
  EXPECT_EQ(mat->GetNumberOfSeams(), 15);
  EXPECT_TRUE(sheets->GetVerificationPassed());
  EXPECT_EQ(sheets->GetNumberOfFailedSheets(), 0);
  EXPECT_LE(sheets->GetMaximumCoverageShortfall(), 1e-9);
}

TEST(vtkCADBoundaryReader, FilletedEdgesAreComplete)
{
  // A box (4 x 2 x 3) with a filleted edge, as CAD rounds one: the sheet of the two faces
  // the fillet rounds ends at the fillet's spine, a centre curve of radius = the fillet's
  // (its balls touch the fillet's whole arc), from the cap below to the cap above; where it
  // meets a cap, the sheet of the fillet and the cap is a cone with its apex on its border,
  // bounded by the fillet's arc (radius 0) and the balls along the two smooth edges where
  // the fillet meets the faces it rounds. Until 2026-11-29 that sheet was filled as the
  // sheet of two faces at a convex edge, which it is not (the fillet's faces covered 86 %:
  // flagged). Also a larger fillet on another edge, two opposite edges of two radii, and
  // the wedge's sloping edge (faces not perpendicular).
  struct Case
  {
    std::string name;
    TopoDS_Shape shape;
    int centreCurves;
  };
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(4, 2, 3).Shape();
  std::vector<TopoDS_Edge> edges;
  for (TopExp_Explorer ex(box, TopAbs_EDGE); ex.More(); ex.Next())
    if (std::none_of(edges.begin(), edges.end(), [&](const TopoDS_Edge& e) { return e.IsSame(ex.Current()); }))
      edges.push_back(TopoDS::Edge(ex.Current()));
  auto filleted = [](const TopoDS_Shape& solid, const std::vector<std::pair<double, TopoDS_Edge>>& rounds) {
    BRepFilletAPI_MakeFillet fillet(solid);
    for (const auto& [radius, edge] : rounds)
      fillet.Add(radius, edge);
    return fillet.Shape();
  };
  const TopoDS_Shape wedge = BRepPrimAPI_MakeWedge(3, 2, 1, 1).Shape();
  std::vector<Case> cases{ { "one-edge", filleted(box, { { 0.3, edges[0] } }), 1 },
    { "edge-4-by-0.8", filleted(box, { { 0.8, edges[4] } }), 1 },
    { "two-edges", filleted(box, { { 0.3, edges[0] }, { 0.5, edges[2] } }), 2 },
    { "wedge", filleted(wedge, { { 0.2, TopoDS::Edge(TopExp_Explorer(wedge, TopAbs_EDGE).Current()) } }), 1 } };
  // Every edge rounded (spheres blend the corners): no convex vertex left, and the MAT is
  // the inner box's (3.4 x 1.4 x 2.4) with every radius 0.3 larger — its seams start at the
  // blends' centres, where three spines (centre curves) meet; until 2026-11-29 nothing
  // started them (no seam, every sheet failed), and the closest point of a blend's octant
  // from its centre searched 200,000 boxes (1.4 s each).
  std::vector<std::pair<double, TopoDS_Edge>> everyEdge;
  for (const TopoDS_Edge& e : edges)
    everyEdge.push_back({ 0.3, e });
  cases.push_back({ "every-edge", filleted(box, everyEdge), 12 });
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    const std::string file = output("cad-fillet-" + c.name + ".step");
    writeStep(c.shape, file);
    const MATPipeline run(file);
    ASSERT_TRUE(run.matErrors.empty()) << run.matErrors;
    ASSERT_TRUE(run.sheetErrors.empty()) << run.sheetErrors;
    vtkMAT3DFilter* mat = run.mat;
    vtkSheetInterpolator* sheets = run.sheets;
    EXPECT_TRUE(mat->GetVerificationPassed());
    EXPECT_EQ(mat->GetNumberOfTopologyProblems(), 0);
    EXPECT_EQ(mat->GetNumberOfJunctions(), 4);
    EXPECT_EQ(mat->GetNumberOfSeams(), 12);
    EXPECT_EQ(mat->GetNumberOfCentreCurves(), c.centreCurves);
    EXPECT_TRUE(sheets->GetVerificationPassed());
    EXPECT_EQ(sheets->GetNumberOfFailedSheets(), 0);
    EXPECT_LE(sheets->GetMaximumCoverageShortfall(), 1e-3);
    if (c.name == "every-edge")
    {
      // The inner box's junctions: (±(1.7 − 0.7), 0, ±(1.2 − 0.7)) about its centre
      // (2, 1, 1.5), radius 0.7 + 0.3 = 1.
      vtkPolyData* out = mat->GetOutput();
      vtkDataArray* type = out->GetCellData()->GetArray(arrays::ElementType);
      int junctions = 0;
      for (vtkIdType cell = 0; cell < out->GetNumberOfCells(); ++cell)
        if (static_cast<int>(type->GetTuple1(cell)) == static_cast<int>(MedialElementType::Junction))
        {
          double x[3];
          out->GetPoint(out->GetCell(cell)->GetPointId(0), x);
          EXPECT_NEAR(std::abs(x[0] - 2.0), 1.0, 1e-9);
          EXPECT_NEAR(x[1], 1.0, 1e-9);
          EXPECT_NEAR(std::abs(x[2] - 1.5), 0.5, 1e-9);
          EXPECT_NEAR(out->GetPointData()->GetArray(arrays::Radius)->GetTuple1(out->GetCell(cell)->GetPointId(0)), 1.0, 1e-9);
          ++junctions;
        }
      EXPECT_EQ(junctions, 4);
    }
    if (c.name != "one-edge")
      continue;
    // The spine in closed form: x = y = 0.3, r = 0.3, from z = 0.3 to 2.7 — where a ball
    // of radius 0.3 touches the caps. The seams from the box's corners at x = y = z end on it.
    vtkPolyData* out = mat->GetOutput();
    vtkDataArray* type = out->GetCellData()->GetArray(arrays::ElementType);
    vtkDataArray* radius = out->GetPointData()->GetArray(arrays::Radius);
    double lowest = INFINITY, highest = -INFINITY;
    int points = 0;
    for (vtkIdType cell = 0; cell < out->GetNumberOfCells(); ++cell)
    {
      if (static_cast<int>(type->GetTuple1(cell)) != static_cast<int>(MedialElementType::CentreCurve))
        continue;
      vtkNew<vtkIdList> ids;
      out->GetCellPoints(cell, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        double x[3];
        out->GetPoint(ids->GetId(k), x);
        EXPECT_NEAR(x[0], 0.3, 1e-10);
        EXPECT_NEAR(x[1], 0.3, 1e-10);
        EXPECT_NEAR(radius->GetTuple1(ids->GetId(k)), 0.3, 1e-10);
        lowest = std::min(lowest, x[2]);
        highest = std::max(highest, x[2]);
        ++points;
      }
    }
    EXPECT_GT(points, 2);
    EXPECT_NEAR(lowest, 0.3, 1e-9);
    EXPECT_NEAR(highest, 2.7, 1e-9);
  }
}

TEST(vtkCADBoundaryReader, PlanarFaceMATIsTheCatalogueMAT)
{
  // The catalogue's free-form plate with holes handed to OpenCASCADE as B-spline edges,
  // written, read back: the same 2D MAT as the catalogue's own boundary.
  for (const std::string shapeName : { "plate-with-holes", "l-shape" })
  {
    SCOPED_TRACE(shapeName);
    const Shape shape = makeShape(shapeName);
    const std::vector<TopoDS_Edge> edges = occtEdges(shape);
    // A compound of the edges (a sketch): the reader takes every edge when there is no face.
    TopoDS_Compound sketch;
    BRep_Builder builder;
    builder.MakeCompound(sketch);
    for (const TopoDS_Edge& e : edges)
      builder.Add(sketch, e);
    const std::string file = output("cad-sketch-" + shapeName + ".step");
    writeStep(sketch, file);
    vtkNew<vtkCADBoundaryReader> reader;
    reader->SetFileName(file.c_str());
    vtkNew<vtkNURBSSource> source;
    source->SetShapeName(shapeName.c_str());
    double radii[2][2];
    int counts[2][2];
    for (int k = 0; k < 2; ++k)
    {
      vtkNew<vtkMAT2DFilter> mat;
      mat->SetInputConnection(k == 0 ? reader->GetOutputPort() : source->GetOutputPort());
      auto errors = ErrorRecorder::watch(mat);
      mat->Update();
      ASSERT_TRUE(errors->Messages.empty()) << errors->Messages;
      EXPECT_TRUE(mat->GetVerificationPassed());
      counts[k][0] = mat->GetNumberOfBranchPoints();
      counts[k][1] = mat->GetNumberOfSegments();
      mat->GetOutput()->GetPointData()->GetArray(arrays::Radius)->GetRange(radii[k]);
    }
    EXPECT_EQ(counts[0][0], counts[1][0]);
    EXPECT_EQ(counts[0][1], counts[1][1]);
    EXPECT_NEAR(radii[0][1], radii[1][1], 1e-9 * radii[1][1]);
  }
}

TEST(vtkCADBoundaryReader, BadFilesSayWhy)
{
  auto expectError = [](const std::string& file, const std::string& words, int dimension = 0) {
    SCOPED_TRACE(file);
    const Read r = readCAD(file, dimension);
    EXPECT_NE(r.errors.find(words), std::string::npos) << r.errors;
    EXPECT_EQ(r.grid->GetNumberOfCells(), 0);
  };
  expectError(output("no-such-file.step"), "cannot open");
  {
    std::ofstream(output("cad-empty.step"));
  }
  expectError(output("cad-empty.step"), "empty");
  {
    std::ofstream(output("cad-text.step")) << "this is not STEP\n";
  }
  expectError(output("cad-text.step"), "not a readable STEP file");
  {
    std::ofstream(output("cad-text.iges")) << "this is not IGES either\n";
  }
  expectError(output("cad-text.iges"), "no shape");
  {
    std::ofstream(output("cad-text.dxf")) << "0\nSECTION\n";
  }
  expectError(output("cad-text.dxf"), "unknown CAD format");
  // Half a STEP file.
  writeStep(BRepPrimAPI_MakeBox(1, 2, 3).Shape(), output("cad-whole.step"));
  {
    std::ifstream in(output("cad-whole.step"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(output("cad-truncated.step")) << text.substr(0, text.size() / 2);
  }
  const Read truncated = readCAD(output("cad-truncated.step"));
  EXPECT_FALSE(truncated.errors.empty());
  EXPECT_EQ(truncated.grid->GetNumberOfCells(), 0);
  // An open shell: three faces of a box asked for as a solid.
  {
    TopoDS_Shape box = BRepPrimAPI_MakeBox(1, 2, 3).Shape();
    TopoDS_Compound open;
    BRep_Builder builder;
    builder.MakeCompound(open);
    int k = 0;
    for (TopExp_Explorer ex(box, TopAbs_FACE); ex.More() && k < 3; ex.Next(), ++k)
      builder.Add(open, ex.Current());
    writeStep(open, output("cad-open.step"));
  }
  expectError(output("cad-open.step"), "do not close up", 3);
  // A face asked for that the file does not have.
  writeStep(BRepPrimAPI_MakeBox(1, 2, 3).Shape(), output("cad-box.step"));
  std::string box;
  {
    std::ifstream in(output("cad-box.step"));
    box.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  // A vertex that names an entity the file does not have: OpenCASCADE 7.6's own transfer
  // dereferences it and crashes; refused before it with OpenCASCADE's own findings.
  const std::size_t vertex = box.find("VERTEX_POINT('',#");
  ASSERT_NE(vertex, std::string::npos);
  const std::size_t vertexEnd = box.find(')', vertex);
  const std::string pointId = box.substr(vertex + 17, vertexEnd - vertex - 17);
  std::ofstream(output("cad-dangling.step")) << box.substr(0, vertex) << "VERTEX_POINT('',#999999"
                                             << box.substr(vertexEnd);
  expectError(output("cad-dangling.step"), "an inconsistent STEP file");
  expectError(output("cad-dangling.step"), "unresolved");
  // A vertex moved 1e-3 off its edges: OpenCASCADE's translator warns, the exact
  // conversion refuses the edge, and the error carries the translator's finding.
  const std::size_t point = box.find("#" + pointId + " = CARTESIAN_POINT");
  ASSERT_NE(point, std::string::npos);
  const std::size_t pointEnd = box.find("));", point);
  std::ofstream(output("cad-moved-vertex.step")) << box.substr(0, pointEnd) << "001" << box.substr(pointEnd);
  expectError(output("cad-moved-vertex.step"), "OpenCASCADE's translator reported");
  // A vertex whose point has two coordinates: OpenCASCADE's transfer dereferences the
  // missing third and would kill the process; with its own signal handlers installed for
  // the read it drops the entity and says so. The process's own handlers are back after.
  struct sigaction before, after;
  sigaction(SIGSEGV, nullptr, &before);
  const std::size_t tupleEnd = box.find("));", point);
  const std::size_t lastComma = box.rfind(',', tupleEnd);
  std::ofstream(output("cad-flat-vertex.step")) << box.substr(0, lastComma) << box.substr(tupleEnd);
  expectError(output("cad-flat-vertex.step"), "Entity was not translated");
  sigaction(SIGSEGV, nullptr, &after);
  EXPECT_EQ(before.sa_handler, after.sa_handler);
  EXPECT_EQ(before.sa_sigaction, after.sa_sigaction);
  EXPECT_EQ(before.sa_flags, after.sa_flags);
  const Read missing = readCAD(output("cad-box.step"), 3, 4);
  EXPECT_NE(missing.errors.find("solid 4 asked for, but the file has 1 solid(s)"), std::string::npos)
    << missing.errors;
}

TEST(vtkCADBoundaryReader, PlanarFaceOfASolidIn2D)
{
  // The bracket (a plate with two round holes and rounded corners, written by OpenCASCADE):
  // its top face read in 2D has the MAT of a domain with two holes.
  const std::string file = std::string(EXACTMAT_TEST_DATA) + "/cad/bracket.step";
  const Read solid = readCAD(file);
  ASSERT_TRUE(solid.errors.empty()) << solid.errors;
  EXPECT_TRUE(gridHasSurfaceCells(solid.grid));
  vtkNew<vtkCADBoundaryReader> reader;
  reader->SetFileName(file.c_str());
  reader->SetDimension(2);
  reader->SetPartIndex(1);
  vtkNew<vtkMAT2DFilter> mat;
  mat->SetInputConnection(reader->GetOutputPort());
  auto errors = ErrorRecorder::watch(mat);
  mat->Update();
  ASSERT_TRUE(errors->Messages.empty()) << errors->Messages;
  EXPECT_EQ(reader->GetNumberOfParts(), 12);
  EXPECT_TRUE(mat->GetVerificationPassed());
  EXPECT_EQ(mat->GetNumberOfBranchPoints(), 6);
  // Two holes: two independent cycles (segments − branch points + 1 component).
  EXPECT_EQ(mat->GetNumberOfSegments() - mat->GetNumberOfBranchPoints() + 1, 6);
  // A cylindrical face is no planar domain: named.
  const Read curved = readCAD(file, 2, 2);
  EXPECT_NE(curved.errors.find("face 2 is a cylinder, not planar"), std::string::npos) << curved.errors;
}

TEST(vtkCADBoundaryReader, PartsByNameWithTheirColours)
{
  // Two named parts, one coloured, written through OpenCASCADE's XDE document.
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  const TDF_Label plate = shapes->AddShape(BRepPrimAPI_MakeBox(4, 3, 0.5).Shape(), false);
  TDataStd_Name::Set(plate, "plate");
  const TDF_Label pin =
    shapes->AddShape(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(10, 0, 0), gp_Dir(0, 0, 1)), 0.5, 2).Shape(), false);
  TDataStd_Name::Set(pin, "pin");
  colours->SetColor(pin, Quantity_Color(1.0, 0.5, 0.0, Quantity_TOC_RGB), XCAFDoc_ColorGen);
  STEPCAFControl_Writer writer;
  ASSERT_TRUE(writer.Transfer(doc, STEPControl_AsIs));
  ASSERT_EQ(writer.Write(output("cad-named.step").c_str()), IFSelect_RetDone);
  XCAFApp_Application::GetApplication()->Close(doc);

  vtkNew<vtkCADBoundaryReader> reader;
  reader->SetFileName(output("cad-named.step").c_str());
  reader->SetPartName("pin");
  auto errors = ErrorRecorder::watch(reader);
  reader->Update();
  ASSERT_TRUE(errors->Messages.empty()) << errors->Messages;
  vtkUnstructuredGrid* grid = reader->GetOutput();
  EXPECT_EQ(reader->GetNumberOfParts(), 2);
  vtkStringArray* names = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("PartNames"));
  ASSERT_TRUE(names);
  ASSERT_EQ(names->GetNumberOfValues(), 2);
  EXPECT_TRUE((names->GetValue(0) == "plate" && names->GetValue(1) == "pin") ||
    (names->GetValue(0) == "pin" && names->GetValue(1) == "plate"));
  double b[6];
  grid->GetBounds(b);
  EXPECT_GT(b[0], 8.0); // the pin (control points reach x = 9), not the plate (x = 0)
  vtkDataArray* colour = grid->GetCellData()->GetArray("FaceColor");
  ASSERT_TRUE(colour);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    EXPECT_NEAR(colour->GetComponent(c, 0), 1.0, 1e-6);
    EXPECT_NEAR(colour->GetComponent(c, 1), 0.5, 1e-2); // sRGB/linear rounding in the file
    EXPECT_NEAR(colour->GetComponent(c, 2), 0.0, 1e-6);
  }
  // An unknown name lists the names there are.
  reader->SetPartName("washer");
  reader->Update();
  EXPECT_NE(errors->Messages.find("no solid named 'washer'"), std::string::npos) << errors->Messages;
  EXPECT_NE(errors->Messages.find("'pin'"), std::string::npos) << errors->Messages;
}

TEST(vtkCADBoundaryReader, ExtrusionMATIsTheSweptMAT)
{
  // Catalogue profiles handed to OpenCASCADE as B-spline edges, extruded by it
  // (BRepPrimAPI_MakePrism), written as STEP and read back: the general 3D MAT of the read
  // solid has the junctions of vtkMAT25DFilter's MAT of the same profile extruded.
  for (const auto& [shapeName, length] : { std::pair<std::string, double>{ "l-shape", 2.5 }, { "star", 2.0 } })
  {
    SCOPED_TRACE(shapeName);
    BRepBuilderAPI_MakeWire wire;
    for (const TopoDS_Edge& e : occtEdges(makeShape(shapeName)))
      wire.Add(e);
    ASSERT_TRUE(wire.IsDone());
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), true);
    const std::string file = output("cad-extruded-" + shapeName + ".step");
    writeStep(BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, length)).Shape(), file);
    vtkNew<vtkCADBoundaryReader> reader;
    reader->SetFileName(file.c_str());
    vtkNew<vtkMAT3DFilter> general;
    general->SetInputConnection(reader->GetOutputPort());
    vtkNew<vtkNURBSSource> profile;
    profile->SetShapeName(shapeName.c_str());
    vtkNew<vtkMAT25DFilter> swept;
    swept->SetInputConnection(profile->GetOutputPort());
    swept->SetLength(length);
    std::vector<std::vector<double>> junctions[2];
    vtkAlgorithm* filters[2] = { general, swept };
    for (int k = 0; k < 2; ++k)
    {
      auto errors = ErrorRecorder::watch(filters[k]);
      filters[k]->Update();
      ASSERT_TRUE(errors->Messages.empty()) << errors->Messages;
      vtkPolyData* out = vtkPolyData::SafeDownCast(filters[k]->GetOutputDataObject(0));
      vtkDataArray* type = out->GetPointData()->GetArray(arrays::PointType);
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        if (type->GetTuple1(i) == 2)
        {
          double x[3];
          out->GetPoint(i, x);
          // Both extrude along +z or −z from the profile's plane: compare |z| to the middle.
          junctions[k].push_back({ std::round(x[0] * 1e7) / 1e7, std::round(x[1] * 1e7) / 1e7,
            std::round(std::abs(std::abs(x[2]) - 0.5 * length) * 1e7) / 1e7 });
        }
      }
      std::sort(junctions[k].begin(), junctions[k].end());
      junctions[k].erase(std::unique(junctions[k].begin(), junctions[k].end()), junctions[k].end());
    }
    EXPECT_TRUE(general->GetVerificationPassed());
    EXPECT_GT(junctions[0].size(), 0u);
    EXPECT_EQ(junctions[0], junctions[1]);
  }
}
