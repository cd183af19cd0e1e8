#include "vtkCADBoundaryReader.h"

#include "CADImport.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkMATReaderErrors.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkMath.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cctype>
#include <string>

vtkStandardNewMacro(vtkCADBoundaryReader);

namespace
{

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
  this->SetPartName(nullptr);
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
  this->NumberOfTranslatorMessages = 0;
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("no FileName set");
    return 0;
  }
  const bool read = exactmat::readReportingErrors(
    this->FileName,
    [&] {
      exactmat::CADImportOptions options;
      options.dimension = this->Dimension == 1 ? 0 : this->Dimension;
      options.part = this->PartIndex;
      options.partName = this->PartName ? this->PartName : "";
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
      output->ShallowCopy(builder.grid());
      if (!cad.faceColours.empty())
      {
        // The file's colours per cell (NaN where its face has none), for display.
        vtkDataArray* ids = output->GetCellData()->GetArray(cad.dimension == 3 ? "FaceId" : "EdgeId");
        vtkNew<vtkDoubleArray> colours;
        colours->SetName("FaceColor");
        colours->SetNumberOfComponents(3);
        colours->SetNumberOfTuples(output->GetNumberOfCells());
        const double none[3] = { vtkMath::Nan(), vtkMath::Nan(), vtkMath::Nan() };
        for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
        {
          const auto it = cad.dimension == 3 && ids ? cad.faceColours.find(static_cast<int>(ids->GetTuple1(c)))
                                                    : cad.faceColours.begin();
          colours->SetTypedTuple(c, it == cad.faceColours.end() ? none : it->second.data());
        }
        output->GetCellData()->AddArray(colours);
      }
      vtkFieldData* fd = output->GetFieldData();
      vtkNew<vtkStringArray> names;
      names->SetName("PartNames");
      for (const std::string& n : cad.partNames)
      {
        names->InsertNextValue(n);
      }
      fd->AddArray(names);
      addFieldString(fd, "PartName", cad.partName);
      addFieldString(fd, "LengthUnit", cad.lengthUnit);
      addFieldString(fd, "SourceFormat", cad.format);
      vtkNew<vtkIntArray> parts;
      parts->SetName("NumberOfParts");
      parts->InsertNextValue(cad.partCount);
      fd->AddArray(parts);
      vtkNew<vtkStringArray> translator;
      translator->SetName("TranslatorMessages");
      for (const std::string& m : cad.translatorMessages)
      {
        translator->InsertNextValue(m);
      }
      fd->AddArray(translator);
      this->NumberOfTranslatorMessages = static_cast<int>(cad.translatorMessages.size());
      if (!cad.translatorMessages.empty())
      {
        // What OpenCASCADE healed or doubted on the way: the shapes read may differ from
        // the file's by its fixes (each checked again by the exact conversion).
        vtkWarningMacro(<< this->FileName << ": OpenCASCADE's " << cad.format << " translator reported "
                        << cad.translatorMessages.size() << " finding(s), first: "
                        << cad.translatorMessages.front() << " (all in field data TranslatorMessages)");
      }
      this->NumberOfParts = cad.partCount;
      this->SetLengthUnit(cad.lengthUnit.c_str());
    },
    [this](const std::string& message) { vtkErrorMacro(<< message); });
  return read ? 1 : 0;
}

void vtkCADBoundaryReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Dimension: " << this->Dimension << "\n";
  os << indent << "PartIndex: " << this->PartIndex << "\n";
  os << indent << "PartName: " << (this->PartName ? this->PartName : "(none)") << "\n";
  os << indent << "NumberOfParts: " << this->NumberOfParts << "\n";
  os << indent << "LengthUnit: " << (this->LengthUnit ? this->LengthUnit : "(none)") << "\n";
}
