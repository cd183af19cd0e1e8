#pragma once
// Small helpers shared by the VTK-level tests.
#include <vtkCommand.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <string>

/// Records VTK error events of an object so tests can assert on the message text.
class ErrorRecorder : public vtkCommand
{
public:
  static ErrorRecorder* New() { return new ErrorRecorder; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    if (data)
    {
      Messages += static_cast<const char*>(data);
    }
  }
  std::string Messages;

  static vtkSmartPointer<ErrorRecorder> watch(vtkObject* o)
  {
    auto r = vtkSmartPointer<ErrorRecorder>::Take(ErrorRecorder::New());
    o->AddObserver(vtkCommand::ErrorEvent, r);
    return r;
  }
};
