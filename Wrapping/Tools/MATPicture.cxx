#include "MATPicture.h"

#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"

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
  vtkNew<vtkPolyDataMapper> matMapper;
  matMapper->SetInputData(mat);
  matMapper->SetScalarModeToUsePointFieldData();
  matMapper->SelectColorArray(exactmat::arrays::Radius);
  matMapper->SetScalarRange(range);
  matMapper->ScalarVisibilityOn();
  vtkNew<vtkActor> matActor;
  matActor->SetMapper(matMapper);
  matActor->GetProperty()->SetLineWidth(3.0);
  matActor->GetProperty()->SetPointSize(9.0);
  matActor->GetProperty()->SetRenderPointsAsSpheres(true);

  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(matMapper->GetLookupTable());
  bar->SetTitle("Radius");
  bar->SetNumberOfLabels(5);
  bar->SetWidth(0.08);
  bar->SetHeight(0.7);
  bar->SetPosition(0.9, 0.15);
  bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
  bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);

  vtkNew<vtkTextActor> caption;
  caption->SetInput(title.c_str());
  caption->GetTextProperty()->SetFontSize(20);
  caption->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  caption->SetPosition(12, 12);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor(boundaryActor);
  renderer->AddActor(matActor);
  renderer->AddActor2D(bar);
  renderer->AddActor2D(caption);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(1200, 800);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  // Look straight at the domain's plane: the camera's view-plane normal is the plane's.
  const exactmat::Boundary2D b = exactmat::Boundary2D::build(exactmat::curvePiecesFromGrid(boundary));
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
