#include "vtkNURBSSource.h"

#include "vtkMATBoundaryConversion.h"

#include "common/InputError.h"
#include "mat25d/SweptSolid.h"
#include "mat2d/Tracer.h"
#include "shapes/Catalogue.h"

#include <exception>
#include <new>

#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <functional>

vtkStandardNewMacro(vtkNURBSSource);

namespace
{
// The solid swept by a 2D shape, as exact conforming Bézier faces (see SweptSolid.h): the
// profile faces are tiled along the profile's MAT.
vtkSmartPointer<vtkUnstructuredGrid> sweptSolid(const exactmat::Shape& shape,
  const exactmat::Sweep& sweep, const std::function<void(double)>& progress)
{
  const exactmat::Boundary2D profile =
    exactmat::Boundary2D::build(exactmat::curvePieces(shape.curves));
  const exactmat::SweepMap map(profile, sweep);
  const exactmat::Generators generators(profile);
  exactmat::MAT2DOptions options;
  options.progress = progress;
  const exactmat::MedialGraph graph = exactmat::computeMAT2D(generators, options);
  exactmat::BoundaryGridBuilder builder;
  for (const exactmat::PatchPiece& face : exactmat::sweptSolidFaces(generators, graph, map))
    builder.addPatch(face.patch, face.entity);
  return builder.grid();
}
} // namespace

struct vtkNURBSSource::Internals
{
  std::vector<exactmat::NurbsCurve> Curves;
  std::vector<exactmat::NurbsSurface> Surfaces;
};

namespace
{
std::vector<double> toVector(vtkDoubleArray* a)
{
  std::vector<double> v;
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    v.push_back(a->GetValue(i));
  }
  return v;
}

exactmat::Vec3List toPoints(vtkPoints* p)
{
  exactmat::Vec3List v;
  for (vtkIdType i = 0; p && i < p->GetNumberOfPoints(); ++i)
  {
    double x[3];
    p->GetPoint(i, x);
    v.emplace_back(x[0], x[1], x[2]);
  }
  return v;
}
} // namespace

vtkNURBSSource::vtkNURBSSource()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(0);
}

vtkNURBSSource::~vtkNURBSSource() = default;

int vtkNURBSSource::GetNumberOfCatalogueShapes()
{
  return static_cast<int>(exactmat::catalogueNames().size());
}

const char* vtkNURBSSource::GetCatalogueShapeName(int i)
{
  const auto& names = exactmat::catalogueNames();
  return (i >= 0 && i < static_cast<int>(names.size())) ? names[i].c_str() : nullptr;
}

bool vtkNURBSSource::SetShapeName(const char* name)
{
  const std::string n = name ? name : "";
  if (n == "user")
  {
    this->SetShape(UserDefined);
    return true;
  }
  const auto& names = exactmat::catalogueNames();
  for (size_t i = 0; i < names.size(); ++i)
  {
    if (names[i] == n)
    {
      this->SetShape(static_cast<int>(i));
      return true;
    }
  }
  vtkErrorMacro("unknown shape '" << n << "'");
  return false;
}

const char* vtkNURBSSource::GetShapeName() const
{
  return this->Shape == UserDefined ? "user" : GetCatalogueShapeName(this->Shape);
}

void vtkNURBSSource::AddCurve(
  int degree, vtkDoubleArray* knots, vtkPoints* points, vtkDoubleArray* weights)
{
  const exactmat::Vec3List p = toPoints(points);
  std::vector<double> w = toVector(weights);
  if (!w.empty() && w.size() != p.size())
  {
    // Keep the mismatch for RequestData to report with the curve's name.
    w.resize(p.size(), -1.0);
  }
  this->Internal->Curves.emplace_back(degree, toVector(knots), p, w);
  this->Modified();
}

void vtkNURBSSource::AddSurface(int degreeU, int degreeV, vtkDoubleArray* knotsU,
  vtkDoubleArray* knotsV, int countU, int countV, vtkPoints* points, vtkDoubleArray* weights)
{
  const exactmat::Vec3List p = toPoints(points);
  std::vector<double> w = toVector(weights);
  if (!w.empty() && w.size() != p.size())
  {
    w.resize(p.size(), -1.0);
  }
  this->Internal->Surfaces.emplace_back(
    degreeU, degreeV, toVector(knotsU), toVector(knotsV), countU, countV, p, w);
  this->Modified();
}

void vtkNURBSSource::RemoveAllEntities()
{
  this->Internal->Curves.clear();
  this->Internal->Surfaces.clear();
  this->Modified();
}

int vtkNURBSSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  try
  {
    exactmat::Shape shape;
    if (this->Shape == UserDefined)
    {
      shape.name = "user";
      shape.curves = this->Internal->Curves;
      shape.surfaces = this->Internal->Surfaces;
      if (shape.curves.empty() == shape.surfaces.empty())
      {
        exactmat::fail(shape.curves.empty()
            ? "user-defined shape: no entities (call AddCurve or AddSurface)"
            : "user-defined shape: give curves (2D) or surfaces (3D), not both");
      }
      shape.dimension = shape.curves.empty() ? 3 : 2;
    }
    else
    {
      exactmat::ShapeParameters p;
      p.width = this->Width;
      p.height = this->Height;
      p.length = this->Length;
      p.radius = this->Radius;
      p.innerRadius = this->InnerRadius;
      p.cornerRadius = this->CornerRadius;
      p.thickness = this->Thickness;
      p.count = this->Count;
      if (!this->GetShapeName())
      {
        exactmat::fail("Shape is ", this->Shape, ", which is neither a catalogue shape (0 to ",
          GetNumberOfCatalogueShapes() - 1, ") nor UserDefined (", static_cast<int>(UserDefined), ")");
      }
      shape = exactmat::makeShape(this->GetShapeName(), p);
    }
    this->UpdateProgress(0.2);
    if (this->Sweep != SweepNone)
    {
      if (shape.dimension != 2)
      {
        exactmat::fail("sweep: '", shape.name, "' is a solid; only 2D shapes (profiles) are "
          "extruded or revolved");
      }
      const exactmat::Sweep sweep = this->Sweep == SweepRevolution
        ? exactmat::Sweep::revolution(this->SweepAngle, exactmat::Vec3(this->SweepAxisOrigin),
            exactmat::Vec3(this->SweepAxisDirection))
        : exactmat::Sweep::extrusion(this->Length);
      output->ShallowCopy(
        sweptSolid(shape, sweep, [this](double f) { this->UpdateProgress(0.2 + 0.7 * f); }));
      return 1;
    }
    exactmat::BoundaryGridBuilder builder;
    builder.addShape(shape);
    this->UpdateProgress(0.6);
    // The boundary must be one the MAT filters accept: closed, non-self-intersecting.
    if (shape.dimension == 2)
    {
      exactmat::Boundary2D::build(exactmat::curvePieces(shape.curves));
    }
    else
    {
      exactmat::Boundary3D::build(exactmat::patchPieces(shape.surfaces));
    }
    output->ShallowCopy(builder.grid());
  }
  catch (const exactmat::InputError& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "out of memory: the input asks for more than this machine can hold");
    return 0;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "internal error: " << e.what());
    return 0;
  }
  return 1;
}

void vtkNURBSSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Shape: " << this->Shape << " (" << (this->GetShapeName() ? this->GetShapeName() : "?")
     << ")\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "Length: " << this->Length << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "InnerRadius: " << this->InnerRadius << "\n";
  os << indent << "CornerRadius: " << this->CornerRadius << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "Count: " << this->Count << "\n";
  os << indent << "Sweep: " << this->Sweep << ", SweepAngle: " << this->SweepAngle << "\n";
  os << indent << "User curves: " << this->Internal->Curves.size()
     << ", user surfaces: " << this->Internal->Surfaces.size() << "\n";
}
