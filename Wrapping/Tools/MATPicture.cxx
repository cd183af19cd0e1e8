#include "MATPicture.h"

#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"

#include "brep/NormalisePieces.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>

#include "nurbs/BezierPatch.h"

namespace
{
// The colour bar of `Radius` for a mapper, and the caption.
void addLegend(vtkRenderer* renderer, vtkPolyDataMapper* mapper, const std::string& title)
{
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(mapper->GetLookupTable());
  bar->SetTitle("Radius");
  bar->SetNumberOfLabels(5);
  bar->SetWidth(0.08);
  bar->SetHeight(0.7);
  bar->SetPosition(0.9, 0.15);
  bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
  bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
  renderer->AddActor2D(bar);
  vtkNew<vtkTextActor> caption;
  caption->SetInput(title.c_str());
  caption->GetTextProperty()->SetFontSize(20);
  caption->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  caption->SetPosition(12, 12);
  renderer->AddActor2D(caption);
}

// A mapper colouring `data` by its point array Radius over [range].
vtkSmartPointer<vtkPolyDataMapper> radiusMapper(vtkPolyData* data, const double range[2])
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(exactmat::arrays::Radius);
  mapper->SetScalarRange(range[0], range[1]);
  mapper->ScalarVisibilityOn();
  return mapper;
}

// Renders the window off-screen and writes it as PNG.
bool savePNG(vtkRenderWindow* window, const std::string& png, std::string& error)
{
  window->Render();
  if (!window->IsCurrent() && !window->GetGenericContext())
  {
    error = "no OpenGL context could be created for off-screen rendering";
    return false;
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(png.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    error = "cannot write '" + png + "'";
    return false;
  }
  return true;
}
} // namespace

bool writeMATPicture(vtkUnstructuredGrid* boundary, vtkPolyData* mat, const std::string& png,
  const std::string& title, std::string& error)
{
  // The boundary, sampled from the exact curves.
  vtkNew<vtkPolyData> curves;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (const exactmat::CurvePiece& piece : exactmat::curvePiecesFromGrid(boundary))
  {
    const int n = 64;
    std::vector<vtkIdType> ids;
    for (int k = 0; k <= n; ++k)
    {
      const exactmat::Vec3 p = piece.curve.evaluate(static_cast<double>(k) / n);
      ids.push_back(points->InsertNextPoint(p.data()));
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  curves->SetPoints(points);
  curves->SetLines(lines);

  vtkNew<vtkPolyDataMapper> boundaryMapper;
  boundaryMapper->SetInputData(curves);
  vtkNew<vtkActor> boundaryActor;
  boundaryActor->SetMapper(boundaryMapper);
  boundaryActor->GetProperty()->SetColor(0.15, 0.15, 0.15);
  boundaryActor->GetProperty()->SetLineWidth(3.0);

  double range[2] = { 0.0, 1.0 };
  mat->GetPointData()->GetArray(exactmat::arrays::Radius)->GetRange(range);
  vtkSmartPointer<vtkPolyDataMapper> matMapper = radiusMapper(mat, range);
  vtkNew<vtkActor> matActor;
  matActor->SetMapper(matMapper);
  matActor->GetProperty()->SetLineWidth(3.0);
  matActor->GetProperty()->SetPointSize(9.0);
  matActor->GetProperty()->SetRenderPointsAsSpheres(true);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor(boundaryActor);
  renderer->AddActor(matActor);
  addLegend(renderer, matMapper, title);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(1200, 800);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  // Look straight at the domain's plane: the camera's view-plane normal is the plane's.
  const exactmat::Boundary2D b = exactmat::buildNormalised(exactmat::curvePiecesFromGrid(boundary));
  double c[3];
  curves->GetCenter(c);
  vtkCamera* camera = renderer->GetActiveCamera();
  const exactmat::Vec3 n = b.plane().normal, up = b.plane().e2;
  camera->SetFocalPoint(c);
  camera->SetPosition(c[0] + n.x(), c[1] + n.y(), c[2] + n.z());
  camera->SetViewUp(up.x(), up.y(), up.z());
  camera->ParallelProjectionOn();
  renderer->ResetCamera();
  camera->Zoom(1.15);
  return savePNG(window, png, error);
}

bool writeSolidMATPicture(vtkUnstructuredGrid* solid, vtkPolyData* mat, const std::string& png,
  const std::string& title, std::string& error)
{
  // The solid, each exact face sampled on a 12×12 grid, translucent.
  vtkNew<vtkPolyData> surface;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  for (const exactmat::PatchPiece& face : exactmat::patchPiecesFromGrid(solid))
  {
    const int n = 12;
    const vtkIdType base = points->GetNumberOfPoints();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        points->InsertNextPoint(face.patch.evaluate(double(i) / n, double(j) / n).data());
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
      {
        const vtkIdType q[4] = { base + i * (n + 1) + j, base + (i + 1) * (n + 1) + j,
          base + (i + 1) * (n + 1) + j + 1, base + i * (n + 1) + j + 1 };
        quads->InsertNextCell(4, q);
      }
  }
  surface->SetPoints(points);
  surface->SetPolys(quads);
  vtkNew<vtkPolyDataMapper> solidMapper;
  solidMapper->SetInputData(surface);
  solidMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> solidActor;
  solidActor->SetMapper(solidMapper);
  solidActor->GetProperty()->SetColor(0.55, 0.6, 0.7);
  solidActor->GetProperty()->SetOpacity(0.18);

  // The sheets coloured by radius; seams, skeletal edges and junctions in dark lines/points.
  double range[2] = { 0.0, 1.0 };
  mat->GetPointData()->GetArray(exactmat::arrays::Radius)->GetRange(range);
  vtkNew<vtkPolyData> sheets, curves;
  sheets->SetPoints(mat->GetPoints());
  sheets->SetPolys(mat->GetPolys());
  sheets->GetPointData()->PassData(mat->GetPointData());
  curves->SetPoints(mat->GetPoints());
  curves->SetLines(mat->GetLines());
  curves->SetVerts(mat->GetVerts());
  vtkSmartPointer<vtkPolyDataMapper> sheetMapper = radiusMapper(sheets, range);
  vtkNew<vtkActor> sheetActor;
  sheetActor->SetMapper(sheetMapper);
  sheetActor->GetProperty()->SetOpacity(0.85);
  // Without sheets (the 3D seam graph) the seams themselves carry the radius colours.
  const bool seamsOnly = mat->GetNumberOfPolys() == 0;
  if (seamsOnly)
    curves->GetPointData()->PassData(mat->GetPointData());
  vtkSmartPointer<vtkPolyDataMapper> curveMapper = radiusMapper(curves, range);
  curveMapper->SetScalarVisibility(seamsOnly);
  vtkNew<vtkActor> curveActor;
  curveActor->SetMapper(curveMapper);
  curveActor->GetProperty()->SetColor(0.1, 0.1, 0.1);
  curveActor->GetProperty()->SetLineWidth(seamsOnly ? 4.0 : 2.5);
  curveActor->GetProperty()->SetPointSize(11.0);
  curveActor->GetProperty()->SetRenderPointsAsSpheres(true);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor(sheetActor);
  renderer->AddActor(curveActor);
  renderer->AddActor(solidActor);
  addLegend(renderer, seamsOnly ? curveMapper : sheetMapper, title);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(1200, 900);
  window->AddRenderer(renderer);
  // An oblique view from the +x +y +z octant, y up.
  double c[3];
  surface->GetCenter(c);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(c);
  camera->SetPosition(c[0] + 1.0, c[1] + 0.9, c[2] + 1.6);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.2);
  return savePNG(window, png, error);
}
