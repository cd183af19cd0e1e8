#include "vtkCADBoundaryReader.h"

#include "CADImport.h"
#include "vtkMATBoundaryConversion.h"

#include "common/InputError.h"

#include <vtkCellArray.h>
#include <vtkContourTriangulator.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cctype>
#include <exception>
#include <new>
#include <string>

vtkStandardNewMacro(vtkCADBoundaryReader);

namespace
{

using exactmat::Vec3;
using exactmat::Vec4;

Vec4 homogeneous(const Vec3& p)
{
  return Vec4(p.x(), p.y(), p.z(), 1.0);
}

// A planar quadrilateral whose corners turn one way about the normal: one bilinear patch.
bool convexQuad(const exactmat::Vec3List& loop, const Vec3& normal)
{
  if (loop.size() != 4)
  {
    return false;
  }
  for (int k = 0; k < 4; ++k)
  {
    const Vec3 a = loop[(k + 1) % 4] - loop[k], b = loop[(k + 2) % 4] - loop[(k + 1) % 4];
    if (a.cross(b).dot(normal) <= 1e-12 * a.norm() * b.norm())
    {
      return false;
    }
  }
  return true;
}

// Linear triangles filling the polygon (holes allowed) with its own vertices only, so its
// straight edges stay whole and conform with the neighbouring faces.
void addPolygon(const exactmat::CADPolygon& polygon, exactmat::BoundaryGridBuilder& builder)
{
  if (polygon.loops.size() == 1 && convexQuad(polygon.loops[0], polygon.normal))
  {
    const exactmat::Vec3List& q = polygon.loops[0];
    exactmat::Vec4List net{ homogeneous(q[0]), homogeneous(q[3]), homogeneous(q[1]), homogeneous(q[2]) };
    builder.addPatch(exactmat::BezierPatch(1, 1, std::move(net)), polygon.face);
    return;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  for (const exactmat::Vec3List& loop : polygon.loops)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    for (const Vec3& p : loop)
    {
      points->InsertNextPoint(p.data());
    }
    const vtkIdType n = static_cast<vtkIdType>(loop.size());
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType ids[2] = { first + k, first + (k + 1) % n };
      lines->InsertNextCell(2, ids);
    }
  }
  vtkNew<vtkPolyData> contours;
  contours->SetPoints(points);
  contours->SetLines(lines);
  vtkNew<vtkCellArray> triangles;
  if (!vtkContourTriangulator::TriangulateContours(
        contours, 0, lines->GetNumberOfCells(), triangles, polygon.normal.data()))
  {
    exactmat::fail("face ", polygon.face, ": its polygon could not be triangulated");
  }
  vtkNew<vtkIdList> ids;
  for (triangles->InitTraversal(); triangles->GetNextCell(ids);)
  {
    if (ids->GetNumberOfIds() != 3)
    {
      exactmat::fail("face ", polygon.face, ": triangulation gave a cell of ", ids->GetNumberOfIds(), " points");
    }
    exactmat::TriangleNet net;
    net.degree = 1;
    net.points.resize(3);
    net.points[exactmat::TriangleNet::index(1, 0, 0)] = homogeneous(Vec3(points->GetPoint(ids->GetId(0))));
    net.points[exactmat::TriangleNet::index(1, 0, 1)] = homogeneous(Vec3(points->GetPoint(ids->GetId(1))));
    net.points[exactmat::TriangleNet::index(1, 1, 0)] = homogeneous(Vec3(points->GetPoint(ids->GetId(2))));
    builder.addTriangle(net, polygon.face);
  }
}

void addFieldString(vtkFieldData* fd, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}

} // namespace

vtkCADBoundaryReader::vtkCADBoundaryReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkCADBoundaryReader::~vtkCADBoundaryReader()
{
  this->SetFileName(nullptr);
  this->SetLengthUnit(nullptr);
}

bool vtkCADBoundaryReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return false;
  }
  std::string name(fileName);
  const auto dot = name.find_last_of('.');
  if (dot == std::string::npos)
  {
    return false;
  }
  std::string ext = name.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == "step" || ext == "stp" || ext == "iges" || ext == "igs";
}

int vtkCADBoundaryReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("no FileName set");
    return 0;
  }
  try
  {
    exactmat::CADImportOptions options;
    options.dimension = this->Dimension == 1 ? 0 : this->Dimension;
    options.part = this->PartIndex;
    const exactmat::CADBoundary cad = exactmat::importCAD(this->FileName, options);
    this->UpdateProgress(0.5);
    exactmat::BoundaryGridBuilder builder;
    for (const auto& c : cad.curves)
    {
      builder.addCurve(c.curve, c.edge, c.t0, c.t1);
    }
    for (const auto& p : cad.patches)
    {
      builder.addPatch(p.patch, p.face, p.u0, p.u1, p.v0, p.v1);
    }
    for (const auto& t : cad.triangles)
    {
      builder.addTriangle(t.net, t.face);
    }
    for (const auto& polygon : cad.polygons)
    {
      addPolygon(polygon, builder);
    }
    output->ShallowCopy(builder.grid());
    vtkFieldData* fd = output->GetFieldData();
    addFieldString(fd, "LengthUnit", cad.lengthUnit);
    addFieldString(fd, "SourceFormat", cad.format);
    vtkNew<vtkIntArray> parts;
    parts->SetName("NumberOfParts");
    parts->InsertNextValue(cad.partCount);
    fd->AddArray(parts);
    this->NumberOfParts = cad.partCount;
    this->SetLengthUnit(cad.lengthUnit.c_str());
  }
  catch (const exactmat::InputError& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "out of memory reading " << this->FileName);
    return 0;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "internal error reading " << this->FileName << ": " << e.what());
    return 0;
  }
  return 1;
}

void vtkCADBoundaryReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Dimension: " << this->Dimension << "\n";
  os << indent << "PartIndex: " << this->PartIndex << "\n";
  os << indent << "NumberOfParts: " << this->NumberOfParts << "\n";
  os << indent << "LengthUnit: " << (this->LengthUnit ? this->LengthUnit : "(none)") << "\n";
}
