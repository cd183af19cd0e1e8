#include "vtkNURBSReader.h"

#include "NURBSJson.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkMATReaderErrors.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>

#include <fstream>
#include <sstream>

vtkStandardNewMacro(vtkNURBSReader);

vtkNURBSReader::vtkNURBSReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkNURBSReader::~vtkNURBSReader()
{
  this->SetFileName(nullptr);
}

int vtkNURBSReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("no FileName set");
    return 0;
  }
  std::ifstream in(this->FileName);
  if (!in)
  {
    vtkErrorMacro("cannot open '" << this->FileName << "' for reading");
    return 0;
  }
  std::stringstream text;
  text << in.rdbuf();
  const bool read = exactmat::readReportingErrors(
    this->FileName,
    [&] {
      const exactmat::Shape shape = exactmat::parseNURBSJson(text.str(), this->FileName);
      this->UpdateProgress(0.5);
      exactmat::BoundaryGridBuilder builder;
      builder.addShape(shape);
      output->ShallowCopy(builder.grid());
    },
    [this](const std::string& message) { vtkErrorMacro(<< message); });
  return read ? 1 : 0;
}

void vtkNURBSReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
