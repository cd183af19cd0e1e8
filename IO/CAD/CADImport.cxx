#include "CADImport.h"
#include "CylinderSection.h"
#include "PlanarTriangulation.h"

#include "common/InputError.h"
#include "nurbs/BezierExtraction.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <BRepBndLib.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_Static.hxx>
#include <OSD.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <IGESControl_Controller.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Controller.hxx>
#include <TDataStd_Name.hxx>
#include <TDF_LabelSequence.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <Quantity_Color.hxx>
#include <TCollection_AsciiString.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Circ.hxx>
#include <gp_Elips.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <csignal>
#include <fstream>
#include <map>
#include <mutex>
#include <set>

namespace exactmat
{
namespace
{

Vec3 vec(const gp_Pnt& p)
{
  return Vec3(p.X(), p.Y(), p.Z());
}

gp_Pnt pnt(const Vec3& p)
{
  return gp_Pnt(p.x(), p.y(), p.z());
}

const char* curveTypeName(GeomAbs_CurveType t)
{
  switch (t)
  {
    case GeomAbs_Line: return "line";
    case GeomAbs_Circle: return "circle";
    case GeomAbs_Ellipse: return "ellipse";
    case GeomAbs_Hyperbola: return "hyperbola";
    case GeomAbs_Parabola: return "parabola";
    case GeomAbs_BezierCurve: return "Bézier curve";
    case GeomAbs_BSplineCurve: return "B-spline curve";
    case GeomAbs_OffsetCurve: return "offset curve";
    default: return "curve of another kind";
  }
}

const char* surfaceTypeName(GeomAbs_SurfaceType t)
{
  switch (t)
  {
    case GeomAbs_Plane: return "plane";
    case GeomAbs_Cylinder: return "cylinder";
    case GeomAbs_Cone: return "cone";
    case GeomAbs_Sphere: return "sphere";
    case GeomAbs_Torus: return "torus";
    case GeomAbs_BezierSurface: return "Bézier surface";
    case GeomAbs_BSplineSurface: return "B-spline surface";
    case GeomAbs_SurfaceOfRevolution: return "surface of revolution";
    case GeomAbs_SurfaceOfExtrusion: return "surface of extrusion";
    case GeomAbs_OffsetSurface: return "offset surface";
    default: return "surface of another kind";
  }
}

bool exactCurveType(GeomAbs_CurveType t)
{
  return t == GeomAbs_Line || t == GeomAbs_Circle || t == GeomAbs_Ellipse ||
    t == GeomAbs_Hyperbola || t == GeomAbs_Parabola || t == GeomAbs_BezierCurve ||
    t == GeomAbs_BSplineCurve;
}

NurbsCurve toNurbs(const Handle(Geom_BSplineCurve) & c)
{
  TColStd_Array1OfReal flat(1, c->NbPoles() + c->Degree() + 1);
  c->KnotSequence(flat);
  KnotVector knots(flat.begin(), flat.end());
  Vec3List points;
  std::vector<double> weights;
  for (int i = 1; i <= c->NbPoles(); ++i)
  {
    points.push_back(vec(c->Pole(i)));
    weights.push_back(c->Weight(i));
  }
  return NurbsCurve(c->Degree(), std::move(knots), points, weights);
}

NurbsSurface toNurbs(const Handle(Geom_BSplineSurface) & s)
{
  const int nu = s->NbUPoles(), nv = s->NbVPoles();
  TColStd_Array1OfReal fu(1, nu + s->UDegree() + 1), fv(1, nv + s->VDegree() + 1);
  s->UKnotSequence(fu);
  s->VKnotSequence(fv);
  Vec3List net;
  std::vector<double> weights;
  for (int i = 1; i <= nu; ++i)
  {
    for (int j = 1; j <= nv; ++j)
    {
      net.push_back(vec(s->Pole(i, j)));
      weights.push_back(s->Weight(i, j));
    }
  }
  return NurbsSurface(s->UDegree(), s->VDegree(), KnotVector(fu.begin(), fu.end()),
    KnotVector(fv.begin(), fv.end()), nu, nv, net, weights);
}

// The unit code OpenCASCADE's xstep.cascade.unit takes for a unit name found in a file.
std::string unitCode(std::string name)
{
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::toupper(c); });
  static const std::map<std::string, std::string> codes{ { "MM", "MM" }, { "MILLIMETRE", "MM" },
    { "MILLIMETER", "MM" }, { "M", "M" }, { "METRE", "M" }, { "METER", "M" }, { "CM", "CM" },
    { "CENTIMETRE", "CM" }, { "CENTIMETER", "CM" }, { "IN", "INCH" }, { "INCH", "INCH" },
    { "FT", "FT" }, { "FOOT", "FT" }, { "UM", "UM" }, { "MICROMETRE", "UM" },
    { "MICROMETER", "UM" }, { "KM", "KM" }, { "KILOMETRE", "KM" }, { "KILOMETER", "KM" },
    { "MIL", "MIL" }, { "MI", "MI" }, { "MILE", "MI" } };
  const auto it = codes.find(name);
  return it == codes.end() ? std::string() : it->second;
}

std::string lowerExtension(const std::string& fileName)
{
  const auto dot = fileName.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : fileName.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// OpenCASCADE's readers print statistics to the terminal through the default messenger;
// only its failures are worth a user's attention, and they come back as errors anyway.
class QuietMessenger
{
public:
  QuietMessenger()
  {
    for (Message_SequenceOfPrinters::Iterator it(Message::DefaultMessenger()->Printers()); it.More(); it.Next())
    {
      Levels.push_back(it.Value()->GetTraceLevel());
      it.Value()->SetTraceLevel(Message_Fail);
    }
  }
  ~QuietMessenger()
  {
    size_t k = 0;
    for (Message_SequenceOfPrinters::Iterator it(Message::DefaultMessenger()->Printers()); it.More() && k < Levels.size(); it.Next())
    {
      it.Value()->SetTraceLevel(Levels[k++]);
    }
  }

private:
  std::vector<Message_Gravity> Levels;
};

// OpenCASCADE's translators catch an access violation on a malformed entity themselves
// (a vertex whose point has two coordinates: the transfer of that root fails and says
// so) — but only while OpenCASCADE's own signal handlers are installed; without them such
// a file kills the process. They are installed for the read (no floating-point traps) and
// the process's own handlers put back after, whatever they were; nested or concurrent
// reads share one installation.
class TranslatorSignals
{
public:
  TranslatorSignals()
  {
    std::lock_guard<std::mutex> lock(mutex());
    if (depth()++ > 0)
      return;
    for (int s = 1; s < NSIG; ++s)
      if (s != SIGKILL && s != SIGSTOP)
        sigaction(s, nullptr, &saved()[s]);
    OSD::SetSignal(OSD_SignalMode_Set, Standard_False);
  }
  ~TranslatorSignals()
  {
    std::lock_guard<std::mutex> lock(mutex());
    if (--depth() > 0)
      return;
    for (int s = 1; s < NSIG; ++s)
      if (s != SIGKILL && s != SIGSTOP)
        sigaction(s, &saved()[s], nullptr);
  }
  TranslatorSignals(const TranslatorSignals&) = delete;
  TranslatorSignals& operator=(const TranslatorSignals&) = delete;

private:
  static std::mutex& mutex()
  {
    static std::mutex m;
    return m;
  }
  static int& depth()
  {
    static int d = 0;
    return d;
  }
  static struct sigaction* saved()
  {
    static struct sigaction handlers[NSIG];
    return handlers;
  }
};

// The file read into an XCAF document: the shape, and the names and colours the file gives
// its parts and faces.
struct CADDocument
{
  Handle(TDocStd_Document) document;
  Handle(XCAFDoc_ShapeTool) shapes;
  Handle(XCAFDoc_ColorTool) colours;
  TopoDS_Shape shape;

  std::string name(const TopoDS_Shape& s) const
  {
    TDF_Label label;
    Handle(TDataStd_Name) name;
    if (!shapes->Search(s, label) || !label.FindAttribute(TDataStd_Name::GetID(), name))
    {
      return "";
    }
    return TCollection_AsciiString(name->Get()).ToCString();
  }

  bool hasColours = false; ///< the file colours something (else no per-face search)

  bool colour(const TopoDS_Shape& s, Vec3& rgb) const
  {
    if (!hasColours)
    {
      return false;
    }
    Quantity_Color c;
    if (colours->GetColor(s, XCAFDoc_ColorSurf, c) || colours->GetColor(s, XCAFDoc_ColorGen, c))
    {
      rgb = Vec3(c.Red(), c.Green(), c.Blue());
      return true;
    }
    return false;
  }

  ~CADDocument()
  {
    if (!document.IsNull())
    {
      XCAFApp_Application::GetApplication()->Close(document);
    }
  }
};

// The translator's checks as "#ENTITY: message" (the file's own entity label; "file" for
// the file as a whole), fails first when `failsOnly`, at most `limit` of them; `count`
// gets how many there were.
std::vector<std::string> checkMessages(const Interface_CheckIterator& checks,
  const Handle(Interface_InterfaceModel) & model, bool failsOnly, std::size_t limit, std::size_t& count)
{
  std::vector<std::string> out;
  count = 0;
  for (Interface_CheckIterator it = checks; it.More(); it.Next())
  {
    const Handle(Interface_Check)& check = it.Value();
    std::string where = "file";
    if (it.Number() > 0 && !model.IsNull() && it.Number() <= model->NbEntities())
    {
      Handle(TCollection_HAsciiString) label = model->StringLabel(model->Value(it.Number()));
      where = label.IsNull() ? "#" + std::to_string(it.Number()) : label->ToCString();
    }
    auto add = [&](const char* kind, const char* text) {
      ++count;
      if (out.size() < limit)
        out.push_back(where + ": " + kind + text);
    };
    for (int i = 1; i <= check->NbFails(); ++i)
      add("", check->CFail(i));
    if (!failsOnly)
      for (int i = 1; i <= check->NbWarnings(); ++i)
        add("warning: ", check->CWarning(i));
  }
  return out;
}

// A file whose syntax check fails (an unresolved reference, an entity of the wrong type)
// is refused before the transfer: OpenCASCADE 7.6 dereferences the missing entity and
// crashes on such a file.
void refuseInconsistentFile(XSControl_Reader& reader, const char* format)
{
  if (reader.Model().IsNull() || reader.Model()->NbEntities() == 0)
    fail("the file holds no shape: no ", format, " entities in it");
  std::size_t count = 0;
  const std::vector<std::string> fails =
    checkMessages(reader.WS()->ModelCheckList(), reader.Model(), true, 3, count);
  if (count == 0)
    return;
  std::string list;
  for (const std::string& f : fails)
    list += (list.empty() ? "" : "; ") + f;
  fail("an inconsistent ", format, " file: OpenCASCADE's check of its entities found ", count, " error(s) (",
    list, count > fails.size() ? "; …" : "", ")");
}

// What the translator reported while turning the file's entities into shapes.
std::vector<std::string> translatorMessages(XSControl_Reader& reader)
{
  std::size_t count = 0;
  std::vector<std::string> out = checkMessages(
    reader.WS()->TransferReader()->TransientProcess()->CheckList(false), reader.Model(), false, 1000, count);
  if (count > out.size())
    out.push_back("… and " + std::to_string(count - out.size()) + " more");
  return out;
}

// Reads the file with OpenCASCADE (its XDE readers: names and colours too), keeping lengths
// in the file's own unit.
void readDocument(const std::string& fileName, CADBoundary& out, CADDocument& doc)
{
  {
    std::ifstream probe(fileName, std::ios::binary);
    if (!probe)
    {
      fail("cannot open the file for reading");
    }
    if (probe.peek() == std::ifstream::traits_type::eof())
    {
      fail("the file is empty");
    }
  }
  const std::string ext = lowerExtension(fileName);
  const QuietMessenger quiet;
  const TranslatorSignals signals;
  // The translators' settings exist once their controllers are initialised.
  STEPControl_Controller::Init();
  IGESControl_Controller::Init();
  // The unit OpenCASCADE converts lengths to is a process-wide setting: restore it after.
  struct UnitSetting
  {
    const char* current = Interface_Static::CVal("xstep.cascade.unit");
    std::string saved = current ? current : "";
    ~UnitSetting()
    {
      if (!saved.empty())
      {
        Interface_Static::SetCVal("xstep.cascade.unit", saved.c_str());
      }
    }
  } unitSetting;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc.document);
  auto setUnit = [&](const std::string& fileUnit) {
    out.lengthUnit = unitCode(fileUnit);
    if (out.lengthUnit.empty())
    {
      out.lengthUnit = "MM";
    }
    Interface_Static::SetCVal("xstep.cascade.unit", out.lengthUnit.c_str());
  };
  if (ext == "step" || ext == "stp")
  {
    out.format = "STEP";
    STEPCAFControl_Reader reader;
    reader.SetNameMode(true);
    reader.SetColorMode(true);
    if (reader.ReadFile(fileName.c_str()) != IFSelect_RetDone)
    {
      fail("not a readable STEP file (OpenCASCADE's STEP reader failed)");
    }
    refuseInconsistentFile(reader.ChangeReader(), "STEP");
    TColStd_SequenceOfAsciiString lengths, angles, solidAngles;
    reader.ChangeReader().FileUnits(lengths, angles, solidAngles);
    setUnit(lengths.IsEmpty() ? "" : lengths.First().ToCString());
    const bool transferred = reader.Transfer(doc.document);
    out.translatorMessages = translatorMessages(reader.ChangeReader());
    if (!transferred)
    {
      fail("the file holds no shape OpenCASCADE can transfer");
    }
  }
  else if (ext == "iges" || ext == "igs")
  {
    out.format = "IGES";
    IGESCAFControl_Reader reader;
    reader.SetNameMode(true);
    reader.SetColorMode(true);
    if (reader.ReadFile(fileName.c_str()) != IFSelect_RetDone)
    {
      fail("not a readable IGES file (OpenCASCADE's IGES reader failed)");
    }
    refuseInconsistentFile(reader, "IGES");
    Handle(TCollection_HAsciiString) unit = reader.IGESModel()->GlobalSection().UnitName();
    setUnit(unit.IsNull() ? "" : unit->ToCString());
    const bool transferred = reader.Transfer(doc.document);
    out.translatorMessages = translatorMessages(reader);
    if (!transferred)
    {
      fail("the file holds no shape OpenCASCADE can transfer");
    }
  }
  else
  {
    fail("unknown CAD format '.", ext, "' (expected .step, .stp, .iges or .igs)");
  }
  doc.shapes = XCAFDoc_DocumentTool::ShapeTool(doc.document->Main());
  doc.colours = XCAFDoc_DocumentTool::ColorTool(doc.document->Main());
  TDF_LabelSequence colourLabels;
  doc.colours->GetColors(colourLabels);
  doc.hasColours = !colourLabels.IsEmpty();
  TDF_LabelSequence free;
  doc.shapes->GetFreeShapes(free);
  if (free.Length() == 1)
  {
    doc.shape = XCAFDoc_ShapeTool::GetShape(free.First());
  }
  else if (free.Length() > 1)
  {
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (TDF_LabelSequence::Iterator it(free); it.More(); it.Next())
    {
      builder.Add(all, XCAFDoc_ShapeTool::GetShape(it.Value()));
    }
    doc.shape = all;
  }
  if (doc.shape.IsNull())
  {
    fail("the file holds no shape");
  }
}

// The exact rational B-spline of an edge's curve over the edge's range, not periodic.
Handle(Geom_BSplineCurve) edgeBSpline(const TopoDS_Edge& e, const std::string& name, double& t0, double& t1)
{
  Handle(Geom_Curve) c = BRep_Tool::Curve(e, t0, t1);
  if (c.IsNull())
  {
    fail(name, " has no 3D curve");
  }
  const GeomAbs_CurveType type = BRepAdaptor_Curve(e).GetType();
  if (!exactCurveType(type))
  {
    fail(name, " is an ", curveTypeName(type), ", which has no exact rational form");
  }
  Handle(Geom_TrimmedCurve) trimmed = new Geom_TrimmedCurve(c, t0, t1);
  Handle(Geom_BSplineCurve) b = GeomConvert::CurveToBSplineCurve(trimmed, Convert_TgtThetaOver2);
  if (b->IsPeriodic())
  {
    b->SetNotPeriodic();
  }
  return b;
}

// Parameter of point p on curve c (projection); fails when p is not on it.
double curveParameter(const Handle(Geom_Curve) & c, const Vec3& p, double tol, const std::string& what)
{
  GeomAPI_ProjectPointOnCurve projection(pnt(p), c);
  if (projection.NbPoints() == 0 || projection.LowerDistance() > tol)
  {
    fail(what, ": the point ", p.transpose(), " that cuts it is not on it");
  }
  return projection.LowerDistanceParameter();
}

// The rational Bézier pieces of an edge, cut at the given points on it.
std::vector<BezierSpan> edgePieces(const TopoDS_Edge& e, const std::string& name,
  const Vec3List& cuts, double tol)
{
  double t0 = 0.0, t1 = 0.0;
  Handle(Geom_BSplineCurve) b = edgeBSpline(e, name, t0, t1);
  for (const Vec3& p : cuts)
  {
    const double t = curveParameter(b, p, tol, name);
    b->InsertKnot(t, 1, 1e-12 * std::max(1.0, std::abs(t1 - t0)), Standard_False);
  }
  return extractBezier(toNurbs(b));
}

struct EdgeOnFace
{
  int edge = -1;
  bool isoV = true;      ///< runs along u at fixed v (else along v at fixed u)
  double fixed = 0.0;    ///< the fixed parameter
  double from = 0.0, to = 0.0; ///< range of the running parameter (sorted)
};

struct FaceTiling
{
  enum Kind
  {
    Natural,
    Planar,
    Disc
  } kind = Natural;
  int face = -1;
  TopoDS_Face topo;
  Handle(Geom_BSplineSurface) surface; // Natural
  std::vector<EdgeOnFace> edges;       // Natural
  std::set<double> uKnots, vKnots;     // Natural: every interior cut, in surface parameters
  int rim = -1;                        // Disc: its edge
  Vec3 centre = Vec3::Zero();          // Disc: the conic's centre
  Vec3 normal = Vec3::UnitZ();         // Planar: the face's outward normal
};

class SolidTiler
{
public:
  SolidTiler(const TopoDS_Shape& solid, double tol)
    : Tol(tol)
  {
    TopExp::MapShapes(solid, TopAbs_FACE, Faces);
    TopExp::MapShapes(solid, TopAbs_EDGE, Edges);
    Cuts.resize(Edges.Extent());
  }

  void tile(CADBoundary& out)
  {
    for (int f = 1; f <= Faces.Extent(); ++f)
    {
      Tilings.push_back(classify(TopoDS::Face(Faces(f)), f - 1));
    }
    // Exchange cuts across edges until every face has all its neighbours' cuts. Each round
    // adds points from a finite set (the faces' knots and their images), so a few rounds do.
    bool changed = true;
    for (int round = 0; changed; ++round)
    {
      if (round == 50)
      {
        fail("the faces' patch layouts do not settle after 50 rounds of exchanging cuts "
             "along their shared edges");
      }
      changed = false;
      for (FaceTiling& t : Tilings)
      {
        if (t.kind == FaceTiling::Natural)
        {
          changed |= exchangeNatural(t);
        }
        else if (t.kind == FaceTiling::Planar)
        {
          changed |= refinePlanar(t);
        }
      }
    }
    for (const FaceTiling& t : Tilings)
    {
      emit(t, out);
    }
    out.faceCount = Faces.Extent();
    out.edgeCount = Edges.Extent();
  }

private:
  std::string faceName(int f) const { return "face " + std::to_string(f); }
  std::string edgeName(int e) const { return "edge " + std::to_string(e); }
  int edgeIndex(const TopoDS_Shape& e) const { return Edges.FindIndex(e) - 1; }

  bool addCut(int edge, const Vec3& p)
  {
    const TopoDS_Edge& e = TopoDS::Edge(Edges(edge + 1));
    const Vec3 a = vec(BRep_Tool::Pnt(TopExp::FirstVertex(e))), b = vec(BRep_Tool::Pnt(TopExp::LastVertex(e)));
    if ((p - a).norm() <= Tol || (p - b).norm() <= Tol)
    {
      return false;
    }
    for (const Vec3& q : Cuts[edge])
    {
      if ((q - p).norm() <= Tol)
      {
        return false;
      }
    }
    Cuts[edge].push_back(p);
    return true;
  }

  FaceTiling classify(const TopoDS_Face& face, int f)
  {
    FaceTiling t;
    t.face = f;
    t.topo = face;
    BRepAdaptor_Surface adaptor(face);
    const GeomAbs_SurfaceType type = adaptor.GetType();
    if (type == GeomAbs_OffsetSurface || type == GeomAbs_OtherSurface)
    {
      fail(faceName(f), " is an ", surfaceTypeName(type), ", which has no exact rational form");
    }
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
    {
      const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
      if (!BRep_Tool::Degenerated(e))
      {
        const GeomAbs_CurveType ct = BRepAdaptor_Curve(e).GetType();
        if (!exactCurveType(ct))
        {
          fail(edgeName(edgeIndex(e)), " (of ", faceName(f), ") is an ", curveTypeName(ct),
            ", which has no exact rational form");
        }
      }
    }
    if (natural(face, t))
    {
      return t;
    }
    std::string why;
    CylinderSectionFace section = cylinderSectionFace(face, Tol, why);
    if (!section.surface.IsNull())
    {
      std::vector<EdgeOnFace> edges;
      for (const CylinderSectionEdge& ce : section.edges)
      {
        EdgeOnFace eo;
        eo.edge = edgeIndex(ce.edge);
        eo.isoV = ce.isoV;
        eo.fixed = ce.fixed;
        edges.push_back(eo);
      }
      adopt(t, section.surface, std::move(edges));
      return t;
    }
    int wires = 0;
    for (TopExp_Explorer ex(face, TopAbs_WIRE); ex.More(); ex.Next())
    {
      ++wires;
    }
    if (type == GeomAbs_Plane)
    {
      std::vector<TopoDS_Edge> edges;
      for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
      {
        edges.push_back(TopoDS::Edge(ex.Current()));
      }
      if (wires == 1 && edges.size() == 1)
      {
        BRepAdaptor_Curve rim(edges[0]);
        if ((rim.GetType() == GeomAbs_Circle || rim.GetType() == GeomAbs_Ellipse) &&
          BRep_Tool::IsClosed(edges[0]))
        {
          t.kind = FaceTiling::Disc;
          t.rim = edgeIndex(edges[0]);
          t.centre = vec(rim.GetType() == GeomAbs_Circle ? rim.Circle().Location() : rim.Ellipse().Location());
          return t;
        }
      }
      t.kind = FaceTiling::Planar;
      gp_Dir n = adaptor.Plane().Axis().Direction();
      if (face.Orientation() == TopAbs_REVERSED)
      {
        n.Reverse();
      }
      t.normal = Vec3(n.X(), n.Y(), n.Z());
      return t;
    }
    fail(faceName(f), " is a trimmed ", surfaceTypeName(type), " (its edges are not the borders "
      "of its parameter rectangle", type == GeomAbs_Cylinder ? ", nor is it " + why : std::string(),
      "): trimmed curved faces are not supported yet");
  }

  // A face whose edges all lie on the border of its parameter rectangle (seams and poles
  // allowed): the surface over that rectangle, exactly.
  bool natural(const TopoDS_Face& face, FaceTiling& t)
  {
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    // Files round parameters: a closed face's range can differ from the period, and start
    // next to 0, by a rounding, which OpenCASCADE's conversions of whole periods refuse.
    auto snap = [](double& a, double& b, double period) {
      if (std::abs((b - a) - period) <= 1e-9 * period)
      {
        const double k = std::round(a / period) * period;
        a = std::abs(a - k) <= 1e-9 * period ? k : a;
        b = a + period;
      }
    };
    if (s->IsUPeriodic())
    {
      snap(u0, u1, s->UPeriod());
    }
    if (s->IsVPeriodic())
    {
      snap(v0, v1, s->VPeriod());
    }
    // ... and can reach past a surface's own bounds (a sphere's poles) by a rounding.
    double su0, su1, sv0, sv1;
    s->Bounds(su0, su1, sv0, sv1);
    if (!s->IsUPeriodic())
    {
      u0 = std::max(u0, su0);
      u1 = std::min(u1, su1);
    }
    if (!s->IsVPeriodic())
    {
      v0 = std::max(v0, sv0);
      v1 = std::min(v1, sv1);
    }
    const double eu = 1e-9 * std::max(1.0, u1 - u0), ev = 1e-9 * std::max(1.0, v1 - v0);
    std::vector<EdgeOnFace> edges;
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
    {
      const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
      if (BRep_Tool::Degenerated(e))
      {
        continue;
      }
      double a, b;
      Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(e, face, a, b);
      if (pc.IsNull())
      {
        return false;
      }
      const gp_Pnt2d pa0 = pc->Value(a), pb0 = pc->Value(b);
      // STEP stores parameter curves as B-splines fitted to the edge's tolerance: an
      // iso-line is then a B-spline whose poles share the fixed coordinate nearly, and the
      // edge itself (the exact 3D curve) lies on the surface's iso-line.
      Geom2dAdaptor_Curve pa(pc, a, b);
      auto isoLine = [&](bool alongU, double fixed, double eps) {
        if (pa.GetType() == GeomAbs_Line)
        {
          return true;
        }
        if (pa.GetType() != GeomAbs_BSplineCurve)
        {
          return false;
        }
        const Handle(Geom2d_BSplineCurve) bs = pa.BSpline();
        for (int k = 1; k <= bs->NbPoles(); ++k)
        {
          if (std::abs((alongU ? bs->Pole(k).Y() : bs->Pole(k).X()) - fixed) > 1e3 * eps)
          {
            return false;
          }
        }
        double c0, c1;
        Handle(Geom_Curve) curve = BRep_Tool::Curve(e, c0, c1);
        Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
        Handle(Geom_Curve) iso = alongU ? surface->VIso(fixed) : surface->UIso(fixed);
        for (int k = 0; k <= 8; ++k)
        {
          GeomAPI_ProjectPointOnCurve projection(curve->Value(c0 + (c1 - c0) * k / 8.0), iso);
          if (projection.NbPoints() == 0 || projection.LowerDistance() > 100 * Tol)
          {
            return false;
          }
        }
        return true;
      };
      EdgeOnFace eo;
      eo.edge = edgeIndex(e);
      if (std::abs(pa0.Y() - pb0.Y()) <= ev && (std::abs(pa0.Y() - v0) <= ev || std::abs(pa0.Y() - v1) <= ev) &&
        isoLine(true, pa0.Y(), ev))
      {
        eo.isoV = true;
        eo.fixed = std::abs(pa0.Y() - v0) <= ev ? v0 : v1;
        eo.from = std::min(pa0.X(), pb0.X());
        eo.to = std::max(pa0.X(), pb0.X());
      }
      else if (std::abs(pa0.X() - pb0.X()) <= eu && (std::abs(pa0.X() - u0) <= eu || std::abs(pa0.X() - u1) <= eu) &&
        isoLine(false, pa0.X(), eu))
      {
        eo.isoV = false;
        eo.fixed = std::abs(pa0.X() - u0) <= eu ? u0 : u1;
        eo.from = std::min(pa0.Y(), pb0.Y());
        eo.to = std::max(pa0.Y(), pb0.Y());
      }
      else
      {
        return false;
      }
      edges.push_back(eo);
    }
    Handle(Geom_RectangularTrimmedSurface) trimmed = new Geom_RectangularTrimmedSurface(s, u0, u1, v0, v1);
    Handle(Geom_BSplineSurface) b;
    try
    {
      b = GeomConvert::SurfaceToBSplineSurface(trimmed);
    }
    catch (const Standard_Failure& e)
    {
      fail(faceName(t.face), " (", surfaceTypeName(BRepAdaptor_Surface(face).GetType()), " over u ", u0,
        "..", u1, ", v ", v0, "..", v1, ") cannot be converted to a rational B-spline: ", e.GetMessageString());
    }
    if (b->IsUPeriodic())
    {
      b->SetUNotPeriodic();
    }
    if (b->IsVPeriodic())
    {
      b->SetVNotPeriodic();
    }
    // A periodic B-spline face stays periodic through the conversion, and its knots then
    // reach beyond the face: keep exactly the face's rectangle.
    const double firstU = b->UKnot(1), lastU = b->UKnot(b->NbUKnots());
    const double firstV = b->VKnot(1), lastV = b->VKnot(b->NbVKnots());
    if (firstU < u0 - eu || lastU > u1 + eu || firstV < v0 - ev || lastV > v1 + ev)
    {
      b->Segment(std::max(u0, firstU), std::min(u1, lastU), std::max(v0, firstV), std::min(v1, lastV));
    }
    adopt(t, b, std::move(edges));
    return true;
  }

  // The face as the B-spline patch b whose sides are the given edges (each along an
  // iso-line of b at its fixed parameter): the patch, cut where the face's edges meet.
  void adopt(FaceTiling& t, const Handle(Geom_BSplineSurface) & b, std::vector<EdgeOnFace> edges)
  {
    t.kind = FaceTiling::Natural;
    t.surface = b;
    t.edges = std::move(edges);
    // The conversion keeps the rectangle's corners (knots at its ends) but may
    // re-parameterise the interior (conics): parameters inside come from projections.
    for (int i = 2; i < b->NbUKnots(); ++i)
    {
      t.uKnots.insert(b->UKnot(i));
    }
    for (int i = 2; i < b->NbVKnots(); ++i)
    {
      t.vKnots.insert(b->VKnot(i));
    }
    // Where two edges meet on one side of the rectangle the tiling needs a corner too.
    for (EdgeOnFace& eo : t.edges)
    {
      Handle(Geom_Curve) iso = eo.isoV ? b->VIso(eo.fixed) : b->UIso(eo.fixed);
      const TopoDS_Edge& e = TopoDS::Edge(Edges(eo.edge + 1));
      double ends[2];
      int k = 0;
      for (const TopoDS_Vertex& v : { TopExp::FirstVertex(e), TopExp::LastVertex(e) })
      {
        ends[k++] = curveParameter(iso, vec(BRep_Tool::Pnt(v)), 100 * Tol, edgeName(eo.edge) + " on " + faceName(t.face));
      }
      std::set<double>& knots = eo.isoV ? t.uKnots : t.vKnots;
      const double lo = eo.isoV ? b->UKnot(1) : b->VKnot(1);
      const double hi = eo.isoV ? b->UKnot(b->NbUKnots()) : b->VKnot(b->NbVKnots());
      eo.from = std::min(ends[0], ends[1]);
      eo.to = std::max(ends[0], ends[1]);
      if (TopExp::FirstVertex(e).IsSame(TopExp::LastVertex(e)))
      {
        // A closed edge (a whole circle) runs along the whole side.
        eo.from = lo;
        eo.to = hi;
      }
      for (double x : { eo.from, eo.to })
      {
        if (inside(iso, x, lo, hi) && !near(iso, knots, x))
        {
          knots.insert(x);
        }
      }
    }
  }

  // Takes the cuts on the face's edges as knots, and gives its knots to its edges as cuts.
  bool exchangeNatural(FaceTiling& t)
  {
    bool changed = false;
    const Handle(Geom_BSplineSurface)& b = t.surface;
    for (const EdgeOnFace& eo : t.edges)
    {
      Handle(Geom_Curve) iso = eo.isoV ? b->VIso(eo.fixed) : b->UIso(eo.fixed);
      std::set<double>& knots = eo.isoV ? t.uKnots : t.vKnots;
      for (const Vec3& p : Cuts[eo.edge])
      {
        const double x = curveParameter(iso, p, 100 * Tol, edgeName(eo.edge) + " on " + faceName(t.face));
        if (inside(iso, x, eo.from, eo.to) && !near(iso, knots, x))
        {
          knots.insert(x);
          changed = true;
        }
      }
      for (double x : knots)
      {
        if (inside(iso, x, eo.from, eo.to))
        {
          changed |= addCut(eo.edge, vec(iso->Value(x)));
        }
      }
    }
    return changed;
  }

  // Parameters are compared through the points they give: projections are only as precise
  // as the point tolerance, and a patch thinner than it would be a sliver.
  bool inside(const Handle(Geom_Curve) & iso, double x, double from, double to) const
  {
    const gp_Pnt p = iso->Value(x);
    return x > from && x < to && p.Distance(iso->Value(from)) > 10 * Tol &&
      p.Distance(iso->Value(to)) > 10 * Tol;
  }

  bool near(const Handle(Geom_Curve) & iso, const std::set<double>& knots, double x) const
  {
    const gp_Pnt p = iso->Value(x);
    for (double k : knots)
    {
      if (p.Distance(iso->Value(k)) <= 10 * Tol)
      {
        return true;
      }
    }
    return false;
  }

  void emit(const FaceTiling& t, CADBoundary& out)
  {
    switch (t.kind)
    {
      case FaceTiling::Natural:
      {
        Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(t.surface->Copy());
        for (double u : t.uKnots)
        {
          b->InsertUKnot(u, 1, 0.0, Standard_False);
        }
        for (double v : t.vKnots)
        {
          b->InsertVKnot(v, 1, 0.0, Standard_False);
        }
        for (BezierPatchSpan& s : extractBezier(toNurbs(b)))
        {
          // Standard form: the sides agree point for point with the same curves cut
          // from the neighbouring faces (caps, sectors and other patches alike).
          out.patches.push_back({ s.patch.inStandardForm(), t.face, s.u0, s.u1, s.v0, s.v1 });
        }
        break;
      }
      case FaceTiling::Disc:
      {
        // Sectors from the centre: a rational quadratic triangle whose side s = 0 is the
        // rim piece (in standard form, end weights 1) and whose other sides are radii.
        const TopoDS_Edge& e = TopoDS::Edge(Edges(t.rim + 1));
        for (const BezierSpan& piece : edgePieces(e, edgeName(t.rim), Cuts[t.rim], 100 * Tol))
        {
          const BezierCurve arc = piece.curve.inStandardForm();
          if (arc.degree() != 2)
          {
            fail(faceName(t.face), ": its rim ", edgeName(t.rim), " is not a conic");
          }
          const Vec3 a = arc.startPoint(), c = arc.endPoint();
          TriangleNet net;
          net.degree = 2;
          net.points.resize(6);
          auto at = [&](int i, int j) -> Vec4& { return net.points[TriangleNet::index(2, i, j)]; };
          auto point = [](const Vec3& p) { return Vec4(p.x(), p.y(), p.z(), 1.0); };
          at(2, 0) = point(t.centre);
          at(1, 0) = point(0.5 * (t.centre + a));
          at(1, 1) = point(0.5 * (t.centre + c));
          at(0, 0) = point(a);
          at(0, 1) = arc.homogeneousPoints()[1];
          at(0, 2) = point(c);
          out.triangles.push_back({ std::move(net), t.face });
        }
        break;
      }
      case FaceTiling::Planar:
      {
        // Linear triangles over the polygon of the loops' vertices and the caps' apexes;
        // a Bézier triangle A, B, apex for each curved piece A→B (side s = 0 the piece).
        const PlanarLoops loops = planarLoops(t);
        std::vector<Vec3List> polygon;
        for (const auto& loop : loops.loops)
        {
          Vec3List points;
          for (const Piece& piece : loop)
          {
            points.push_back(piece.a);
            if (piece.cap)
            {
              if (!piece.fits)
              {
                fail(faceName(t.face), ": a piece of ", edgeName(piece.edge), " from ",
                  piece.a.transpose(), " turns too sharply to be tiled exactly");
              }
              points.push_back(piece.apex);
              out.triangles.push_back({ capTriangle(piece), t.face });
            }
          }
          polygon.push_back(std::move(points));
        }
        emitPolygon(polygon, t, out);
        break;
      }
    }
  }

  // A planar polygon (holes allowed) as linear triangles on its own vertices, so its
  // segments stay whole and conform; a convex quadrilateral as one bilinear patch.
  void emitPolygon(const std::vector<Vec3List>& loops, const FaceTiling& t, CADBoundary& out)
  {
    auto point = [](const Vec3& p) { return Vec4(p.x(), p.y(), p.z(), 1.0); };
    if (loops.size() == 1 && loops[0].size() == 4)
    {
      const Vec3List& q = loops[0];
      bool convex = true;
      for (int k = 0; k < 4; ++k)
      {
        const Vec3 a = q[(k + 1) % 4] - q[k], b = q[(k + 2) % 4] - q[(k + 1) % 4];
        convex &= std::abs(a.cross(b).dot(t.normal)) > 1e-9 * a.norm() * b.norm() &&
          (a.cross(b).dot(t.normal) > 0) == ((q[1] - q[0]).cross(q[2] - q[1]).dot(t.normal) > 0);
      }
      if (convex)
      {
        Vec4List net{ point(q[0]), point(q[3]), point(q[1]), point(q[2]) };
        out.patches.push_back({ BezierPatch(1, 1, std::move(net)), t.face, 0.0, 1.0, 0.0, 1.0 });
        return;
      }
    }
    Vec3List points;
    for (const Vec3List& loop : loops)
    {
      points.insert(points.end(), loop.begin(), loop.end());
    }
    std::vector<std::array<int, 3>> triangles;
    try
    {
      triangles = triangulatePlanarLoops(loops, t.normal);
    }
    catch (const InputError& e)
    {
      fail(faceName(t.face), ": ", e.what());
    }
    for (const auto& tri : triangles)
    {
      TriangleNet net;
      net.degree = 1;
      net.points.resize(3);
      net.points[TriangleNet::index(1, 0, 0)] = point(points[tri[0]]);
      net.points[TriangleNet::index(1, 0, 1)] = point(points[tri[1]]);
      net.points[TriangleNet::index(1, 1, 0)] = point(points[tri[2]]);
      out.triangles.push_back({ std::move(net), t.face });
    }
  }

  // One piece of a planar face's loop, in the loop's direction: straight from a to b, or a
  // curved Bézier piece with the apex of its cap on the material side.
  struct Piece
  {
    Vec3 a = Vec3::Zero(), b = Vec3::Zero(), apex = Vec3::Zero();
    bool cap = false;
    BezierCurve curve; // standard form, a → b
    int edge = -1;
    bool fits = true;  // the curve lies inside the wedge its cap allows
  };
  struct PlanarLoops
  {
    std::vector<std::vector<Piece>> loops;
  };

  static TriangleNet capTriangle(const Piece& piece)
  {
    // r-corner a, t-corner b, s-corner the apex: side s = 0 is the curve, the other two are
    // straight (evenly spaced points, weight 1), the interior points are the flat triangle's.
    const int p = piece.curve.degree();
    TriangleNet net;
    net.degree = p;
    net.points.resize(static_cast<size_t>(p + 1) * (p + 2) / 2);
    for (int i = 0; i <= p; ++i)
    {
      for (int j = 0; i + j <= p; ++j)
      {
        Vec4& h = net.points[TriangleNet::index(p, i, j)];
        if (i == 0)
        {
          h = piece.curve.homogeneousPoints()[j];
          continue;
        }
        const double si = double(i) / p, tj = double(j) / p, rk = 1.0 - si - tj;
        const Vec3 x = si * piece.apex + tj * piece.b + rk * piece.a;
        h = Vec4(x.x(), x.y(), x.z(), 1.0);
      }
    }
    return net;
  }

  // The loops of a planar face as pieces cut at the current cuts, outer loop first.
  PlanarLoops planarLoops(const FaceTiling& t)
  {
    PlanarLoops result;
    const TopoDS_Wire outer = BRepTools::OuterWire(t.topo);
    std::vector<TopoDS_Wire> wires{ outer };
    for (TopExp_Explorer ex(t.topo, TopAbs_WIRE); ex.More(); ex.Next())
    {
      if (!ex.Current().IsSame(outer))
      {
        wires.push_back(TopoDS::Wire(ex.Current()));
      }
    }
    for (size_t w = 0; w < wires.size(); ++w)
    {
      std::vector<Piece> loop;
      for (BRepTools_WireExplorer we(wires[w], t.topo); we.More(); we.Next())
      {
        const TopoDS_Edge& e = we.Current();
        const int id = edgeIndex(e);
        const bool reversed = e.Orientation() == TopAbs_REVERSED;
        if (BRepAdaptor_Curve(e).GetType() == GeomAbs_Line)
        {
          const Vec3 a = vec(BRep_Tool::Pnt(TopExp::FirstVertex(e, Standard_True)));
          const Vec3 b = vec(BRep_Tool::Pnt(TopExp::LastVertex(e, Standard_True)));
          Vec3List points = Cuts[id];
          std::sort(points.begin(), points.end(), [&](const Vec3& p, const Vec3& q) {
            return (p - a).dot(b - a) < (q - a).dot(b - a);
          });
          points.insert(points.begin(), a);
          points.push_back(b);
          for (size_t k = 0; k + 1 < points.size(); ++k)
          {
            Piece piece;
            piece.a = points[k];
            piece.b = points[k + 1];
            piece.edge = id;
            loop.push_back(piece);
          }
          continue;
        }
        std::vector<BezierSpan> spans = edgePieces(e, edgeName(id), Cuts[id], 100 * Tol);
        if (reversed)
        {
          std::reverse(spans.begin(), spans.end());
        }
        for (const BezierSpan& span : spans)
        {
          Piece piece;
          piece.curve = (reversed ? span.curve.reversed() : span.curve).inStandardForm();
          piece.a = piece.curve.startPoint();
          piece.b = piece.curve.endPoint();
          piece.cap = piece.curve.degree() > 1;
          piece.edge = id;
          loop.push_back(piece);
        }
      }
      if (loop.size() < 2)
      {
        fail(faceName(t.face), ": a loop of ", loop.size(), " piece(s)");
      }
      // The material is on the left of an outer loop that turns counter-clockwise about the
      // normal, and on the left of a hole that turns clockwise.
      double area = 0.0;
      for (const Piece& piece : loop)
      {
        area += piece.a.cross(piece.b).dot(t.normal);
      }
      const double side = ((w == 0) == (area > 0.0)) ? 1.0 : -1.0;
      for (Piece& piece : loop)
      {
        if (!piece.cap)
        {
          continue;
        }
        const Vec3 d = piece.b - piece.a;
        const double length = d.norm();
        const Vec3 x = d / length, y = side * t.normal.cross(x);
        piece.apex = piece.a + 0.5 * length * x + 0.75 * length * y;
        // The cap A, B, apex (its roof has slope 3/2) holds the curve when the control points
        // stay in the wedges of slope 3/4 at both ends (then so does the curve, in their
        // hull): no crossing of the straight sides. Conic arcs of up to 60° fit.
        for (int k = 0; k <= piece.curve.degree(); ++k)
        {
          const Vec3 q = piece.curve.controlPoint(k) - piece.a;
          const double qx = q.dot(x), qy = q.dot(y), room = 0.75 * std::min(qx, length - qx);
          if (qx < -Tol || qx > length + Tol || std::abs(qy) > room + Tol)
          {
            piece.fits = false;
          }
        }
      }
      result.loops.push_back(std::move(loop));
    }
    return result;
  }

  // Cuts a planar face's curved pieces until every cap holds its curve and no cap crosses
  // or covers another part of the face. Returns true when it added a cut.
  bool refinePlanar(const FaceTiling& t)
  {
    const PlanarLoops loops = planarLoops(t);
    std::vector<const Piece*> pieces;
    for (const auto& loop : loops.loops)
    {
      for (const Piece& piece : loop)
      {
        pieces.push_back(&piece);
      }
    }
    std::vector<bool> split(pieces.size(), false);
    for (size_t k = 0; k < pieces.size(); ++k)
    {
      split[k] = pieces[k]->cap && !pieces[k]->fits;
    }
    // The polygon's segments: a→b for straight pieces, a→apex→b for caps.
    auto segments = [](const Piece& piece) {
      std::vector<std::pair<Vec3, Vec3>> s;
      if (piece.cap)
      {
        s.push_back({ piece.a, piece.apex });
        s.push_back({ piece.apex, piece.b });
      }
      else
      {
        s.push_back({ piece.a, piece.b });
      }
      return s;
    };
    const Vec3 n = t.normal;
    auto orient = [&](const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a).dot(n); };
    auto cross = [&](const std::pair<Vec3, Vec3>& s, const std::pair<Vec3, Vec3>& u) {
      const double scale = Tol * std::max((s.second - s.first).norm(), (u.second - u.first).norm());
      const double d1 = orient(s.first, s.second, u.first), d2 = orient(s.first, s.second, u.second);
      const double d3 = orient(u.first, u.second, s.first), d4 = orient(u.first, u.second, s.second);
      return ((d1 > scale && d2 < -scale) || (d1 < -scale && d2 > scale)) &&
        ((d3 > scale && d4 < -scale) || (d3 < -scale && d4 > scale));
    };
    auto inside = [&](const Piece& cap, const Vec3& q) {
      const double scale = Tol * (cap.b - cap.a).squaredNorm();
      return orient(cap.a, cap.b, q) * orient(cap.a, cap.b, cap.apex) > scale &&
        orient(cap.b, cap.apex, q) * orient(cap.b, cap.apex, cap.a) > scale &&
        orient(cap.apex, cap.a, q) * orient(cap.apex, cap.a, cap.b) > scale;
    };
    // Pairs whose extents along a direction of the plane overlap (sweep and prune): faces
    // with hundreds of holes have thousands of pieces.
    const Vec3 axis = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    std::vector<std::pair<double, double>> extent(pieces.size());
    for (size_t k = 0; k < pieces.size(); ++k)
    {
      const Piece& p = *pieces[k];
      double lo = std::min(p.a.dot(axis), p.b.dot(axis)), hi = std::max(p.a.dot(axis), p.b.dot(axis));
      if (p.cap)
      {
        lo = std::min(lo, p.apex.dot(axis));
        hi = std::max(hi, p.apex.dot(axis));
      }
      extent[k] = { lo - Tol, hi + Tol };
    }
    std::vector<size_t> order(pieces.size());
    for (size_t k = 0; k < order.size(); ++k)
    {
      order[k] = k;
    }
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return extent[a].first < extent[b].first; });
    auto vertices = [](const Piece& p) {
      std::vector<Vec3> v{ p.a, p.b };
      if (p.cap)
      {
        v.push_back(p.apex);
      }
      return v;
    };
    for (size_t ok = 0; ok < order.size(); ++ok)
    {
      const size_t k0 = order[ok];
      for (size_t om = ok + 1; om < order.size() && extent[order[om]].first <= extent[k0].second; ++om)
      {
        const size_t k = std::min(k0, order[om]), m = std::max(k0, order[om]);
        bool clash = false;
        for (const auto& s : segments(*pieces[k]))
        {
          for (const auto& u : segments(*pieces[m]))
          {
            clash |= cross(s, u);
          }
        }
        // Overlapping triangles cross or hold one another's corners.
        for (const Vec3& q : vertices(*pieces[m]))
        {
          clash |= pieces[k]->cap && inside(*pieces[k], q);
        }
        for (const Vec3& q : vertices(*pieces[k]))
        {
          clash |= pieces[m]->cap && inside(*pieces[m], q);
        }
        if (clash)
        {
          if (!pieces[k]->cap && !pieces[m]->cap)
          {
            fail(faceName(t.face), ": its boundary crosses itself near ", pieces[k]->a.transpose());
          }
          split[k] = split[k] || pieces[k]->cap;
          split[m] = split[m] || pieces[m]->cap;
        }
      }
    }
    bool changed = false;
    for (size_t k = 0; k < pieces.size(); ++k)
    {
      if (split[k])
      {
        changed |= addCut(pieces[k]->edge, pieces[k]->curve.evaluate(0.5));
      }
    }
    return changed;
  }

  double Tol;
  TopTools_IndexedMapOfShape Faces, Edges;
  std::vector<Vec3List> Cuts; // per edge: interior points where patch corners must lie
  std::vector<FaceTiling> Tilings;
};

double shapeTolerance(const TopoDS_Shape& shape)
{
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  if (box.IsVoid())
  {
    fail("the part has no geometry");
  }
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  return 1e-9 * Vec3(x1 - x0, y1 - y0, z1 - z0).norm();
}

// The colour of each face the file gives one (or its part, when the part has one).
void faceColours(const CADDocument& doc, const TopoDS_Shape& part, CADBoundary& out)
{
  Vec3 partColour;
  const bool partHasColour = doc.colour(part, partColour);
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(part, TopAbs_FACE, faces);
  for (int f = 1; f <= faces.Extent(); ++f)
  {
    Vec3 rgb;
    if (doc.colour(faces(f), rgb))
    {
      out.faceColours[f - 1] = rgb;
    }
    else if (partHasColour)
    {
      out.faceColours[f - 1] = partColour;
    }
  }
}

// Index of the part named `name` (names listed in the error when there is none).
int partByName(const std::vector<std::string>& names, const std::string& name, const char* what)
{
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
  {
    std::string known;
    for (const std::string& n : names)
    {
      known += (known.empty() ? "'" : ", '") + n + "'";
    }
    fail("no ", what, " named '", name, "' (the file's ", what, "s are named: ",
      known.empty() ? "none" : known, ")");
  }
  return static_cast<int>(it - names.begin());
}

void importSolid(const TopoDS_Shape& solid, CADBoundary& out)
{
  for (TopExp_Explorer ex(solid, TopAbs_SHELL); ex.More(); ex.Next())
  {
    if (!BRep_Tool::IsClosed(ex.Current()))
    {
      fail("a shell of the solid is not closed (it has free edges): not a solid boundary");
    }
  }
  SolidTiler tiler(solid, shapeTolerance(solid));
  tiler.tile(out);
}

void importPlanar(const TopoDS_Shape& shape, int part, const std::string& partName,
  const CADDocument& doc, CADBoundary& out)
{
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  // Faces in TopExp::MapShapes order: face N here is FaceId N of the solid read in 3D.
  TopTools_IndexedMapOfShape faceMap;
  TopExp::MapShapes(shape, TopAbs_FACE, faceMap);
  std::vector<TopoDS_Face> faces;
  for (int f = 1; f <= faceMap.Extent(); ++f)
  {
    faces.push_back(TopoDS::Face(faceMap(f)));
  }
  TopoDS_Shape source = shape;
  if (!faces.empty())
  {
    out.partCount = static_cast<int>(faces.size());
    // Face names only when asked for by name: each is a search of the whole document.
    if (!partName.empty())
    {
      for (const TopoDS_Face& f : faces)
      {
        out.partNames.push_back(doc.name(f));
      }
      part = partByName(out.partNames, partName, "face");
    }
    if (part < 0 || part >= out.partCount)
    {
      fail("face ", part, " asked for, but the file has ", out.partCount, " face(s)");
    }
    const GeomAbs_SurfaceType type = BRepAdaptor_Surface(faces[part]).GetType();
    if (type != GeomAbs_Plane)
    {
      fail("face ", part, " is a ", surfaceTypeName(type), ", not planar: a 2D MAT needs a "
        "planar face (or read the solid in 3D)");
    }
    source = faces[part];
    out.faceCount = 1;
    out.partName = out.partNames.empty() ? doc.name(source) : out.partNames[part];
    Vec3 rgb;
    if (doc.colour(source, rgb))
    {
      out.faceColours[part] = rgb;
    }
  }
  else
  {
    out.partCount = 1;
  }
  const double tol = shapeTolerance(source);
  int count = 0;
  for (TopExp_Explorer ex(source, TopAbs_EDGE); ex.More(); ex.Next())
  {
    const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
    if (BRep_Tool::Degenerated(e))
    {
      continue;
    }
    const int id = edges.FindIndex(e) - 1;
    for (BezierSpan& s : edgePieces(e, "edge " + std::to_string(id), {}, tol))
    {
      out.curves.push_back({ std::move(s.curve), id, s.t0, s.t1 });
    }
    ++count;
  }
  if (count == 0)
  {
    fail("the part has no edges");
  }
  out.edgeCount = count;
}

} // namespace

CADBoundary importCAD(const std::string& fileName, const CADImportOptions& options)
{
  CADBoundary out;
  // A conversion that fails on a shape OpenCASCADE has healed or doubted says so: the
  // translator's first finding is often the cause (a vertex off its edge's curve).
  auto translatorNote = [&out]() {
    if (out.translatorMessages.empty())
      return std::string();
    return " (OpenCASCADE's translator reported " + std::to_string(out.translatorMessages.size()) +
      " finding(s) on this file, first: " + out.translatorMessages.front() + ")";
  };
  try
  {
    CADDocument doc;
    readDocument(fileName, out, doc);
    const TopoDS_Shape& shape = doc.shape;
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next())
    {
      solids.push_back(ex.Current());
    }
    int faces = 0;
    bool planar = true;
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next())
    {
      ++faces;
      planar &= BRepAdaptor_Surface(TopoDS::Face(ex.Current())).GetType() == GeomAbs_Plane;
    }
    // IGES (and some STEP files) carry a solid as loose faces: sew them and close the shell.
    if (solids.empty() && faces > 1 && options.dimension != 2)
    {
      BRepBuilderAPI_Sewing sewing(shapeTolerance(shape) * 1e3);
      sewing.Add(shape);
      sewing.Perform();
      for (TopExp_Explorer ex(sewing.SewedShape(), TopAbs_SHELL); ex.More(); ex.Next())
      {
        if (BRep_Tool::IsClosed(ex.Current()))
        {
          BRepBuilderAPI_MakeSolid make(TopoDS::Shell(ex.Current()));
          if (make.IsDone())
          {
            solids.push_back(make.Solid());
          }
        }
      }
      if (solids.empty() && options.dimension == 3)
      {
        fail("the ", faces, " faces in the file do not close up into a solid (open shell)");
      }
    }
    const bool solid = options.dimension == 3 || (options.dimension == 0 && !solids.empty() && !(planar && faces == 1));
    if (solid)
    {
      if (solids.empty())
      {
        fail("the file holds no solid");
      }
      out.dimension = 3;
      out.partCount = static_cast<int>(solids.size());
      for (const TopoDS_Shape& s : solids)
      {
        out.partNames.push_back(doc.name(s));
      }
      const int part = options.partName.empty() ? options.part : partByName(out.partNames, options.partName, "solid");
      if (part < 0 || part >= out.partCount)
      {
        fail("solid ", part, " asked for, but the file has ", out.partCount, " solid(s)");
      }
      out.partName = out.partNames[part];
      importSolid(solids[part], out);
      faceColours(doc, solids[part], out);
    }
    else
    {
      out.dimension = 2;
      importPlanar(shape, options.part, options.partName, doc, out);
    }
  }
  catch (const InputError& e)
  {
    throw InputError(fileName + ": " + e.what() + translatorNote());
  }
  catch (const Standard_Failure& e)
  {
    throw InputError(fileName + ": OpenCASCADE failed: " + e.GetMessageString() + translatorNote());
  }
  return out;
}

} // namespace exactmat
