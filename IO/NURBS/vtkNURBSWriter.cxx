#include "vtkNURBSWriter.h"

#include "NURBSJson.h"
#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"

#include "common/InputError.h"
#include "nurbs/BezierExtraction.h"

#include <exception>
#include <new>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkUnstructuredGrid.h>

#include <fstream>
#include <map>

vtkStandardNewMacro(vtkNURBSWriter);

vtkNURBSWriter::vtkNURBSWriter() = default;

vtkNURBSWriter::~vtkNURBSWriter()
{
  this->SetFileName(nullptr);
}

int vtkNURBSWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

namespace
{
using namespace exactmat;

// Curves of one entity, in cell order, grouped into runs that join end to start.
void appendCurves(vtkUnstructuredGrid* grid, Shape& shape, std::vector<int>& ids)
{
  const std::vector<CurvePiece> pieces = curvePiecesFromGrid(grid);
  vtkDataArray* ranges = grid->GetCellData()->GetArray(arrays::ParameterRange);
  const bool haveRanges = ranges && ranges->GetNumberOfComponents() == 2 &&
    ranges->GetNumberOfTuples() == static_cast<vtkIdType>(pieces.size());
  size_t k = 0;
  while (k < pieces.size())
  {
    std::vector<BezierCurve> run{ pieces[k].curve };
    std::vector<double> breaks;
    if (haveRanges)
    {
      breaks = { ranges->GetComponent(k, 0), ranges->GetComponent(k, 1) };
    }
    size_t next = k + 1;
    while (next < pieces.size() && pieces[next].entity == pieces[k].entity &&
      pieces[next].curve.degree() == run.front().degree() &&
      pieces[next].curve.startPoint() == run.back().endPoint() &&
      (!haveRanges || ranges->GetComponent(next, 0) == breaks.back()))
    {
      run.push_back(pieces[next].curve);
      if (haveRanges)
      {
        breaks.push_back(ranges->GetComponent(next, 1));
      }
      ++next;
    }
    shape.curves.push_back(joinBezier(run, breaks));
    ids.push_back(pieces[k].entity);
    k = next;
  }
}

void appendSurfaces(vtkUnstructuredGrid* grid, Shape& shape, std::vector<int>& ids)
{
  const std::vector<PatchPiece> pieces = patchPiecesFromGrid(grid);
  vtkDataArray* ranges = grid->GetCellData()->GetArray(arrays::ParameterRange);
  const bool haveRanges = ranges && ranges->GetNumberOfComponents() == 4 &&
    ranges->GetNumberOfTuples() == static_cast<vtkIdType>(pieces.size());
  for (size_t k = 0; k < pieces.size(); ++k)
  {
    const BezierPatch& p = pieces[k].patch;
    NurbsSurface s = p.toNurbs();
    if (haveRanges && !pieces[k].triangle)
    {
      KnotVector ku = s.knotsU(), kv = s.knotsV();
      for (double& u : ku)
        u = u == 0.0 ? ranges->GetComponent(k, 0) : ranges->GetComponent(k, 1);
      for (double& v : kv)
        v = v == 0.0 ? ranges->GetComponent(k, 2) : ranges->GetComponent(k, 3);
      s = NurbsSurface(p.degreeU(), p.degreeV(), ku, kv, p.degreeU() + 1, p.degreeV() + 1,
        p.homogeneousNet());
    }
    shape.surfaces.push_back(std::move(s));
    ids.push_back(pieces[k].entity);
  }
}
} // namespace

void vtkNURBSWriter::WriteData()
{
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(this->GetInput());
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("no FileName set");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  std::string text;
  try
  {
    exactmat::Shape shape;
    std::vector<int> ids;
    if (exactmat::gridHasSurfaceCells(grid))
    {
      appendSurfaces(grid, shape, ids);
    }
    else
    {
      appendCurves(grid, shape, ids);
    }
    text = exactmat::writeNURBSJson(shape, ids);
  }
  catch (const exactmat::InputError& e)
  {
    vtkErrorMacro(<< e.what());
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "internal error: " << e.what());
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  std::ofstream out(this->FileName);
  if (!out || !(out << text))
  {
    vtkErrorMacro("cannot write '" << this->FileName << "'");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  }
}

void vtkNURBSWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
