// exactmat — the medial axis transform of exact NURBS boundaries from the command line.
//
//   exactmat 2d [INPUT] [-o OUT.vtp] [--tolerance T | --step S [--branch-step B]]
//               [--png OUT.png] [--shape NAME]
//   exactmat extrude [PROFILE] --length L [-o OUT.vtp] [--png OUT.png] [...]
//   exactmat revolve [PROFILE] [--angle DEG] [--axis PX,PY,PZ[,DX,DY,DZ]] [-o OUT.vtp] [...]
//   exactmat 3d [SOLID] [-o OUT.vtp] [--tolerance T | --step S [--branch-step B]] [--max-step H] [--png OUT.png]
//   exactmat shapes
//
// INPUT is a .vtu of (rational) Bézier cells, ExactMAT's .json NURBS format, or a STEP /
// IGES part (read exactly); without one, the bundled catalogue shape plate-with-holes (or
// --shape NAME) is used.
#include "Batch.h"
#include "MATPicture.h"

#include "vtkCADBoundaryReader.h"
#include "vtkExactMATArrayNames.h"
#include "vtkMAT25DFilter.h"
#include "vtkMAT2DFilter.h"
#include "vtkMAT3DFilter.h"
#include "vtkSheetInterpolator.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkNURBSReader.h"
#include "vtkNURBSSource.h"

#include "brep/NormalisePieces.h"
#include "common/InputError.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkIdList.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkPoints.h>
#include <vtkLogger.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <cerrno>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace
{
// Exit codes (README): what a script needs to tell apart.
constexpr int ExitInputError = 1;   ///< the input is invalid or the MAT cannot be computed
constexpr int ExitUsage = 2;        ///< the command line is wrong
constexpr int ExitVerification = 3; ///< the MAT was written but its self-verification failed
constexpr int ExitOutputError = 4;  ///< the result could not be written

const char* Usage = R"(usage:
  exactmat INPUT [options]  2d or 3d, chosen by INPUT's cells (curves or faces)
  exactmat 2d [INPUT] [-o OUT.vtp] [--tolerance T | --step S [--branch-step B]]
              [--png OUT.png] [--shape NAME] [--verify-tolerance V]
  exactmat extrude [PROFILE] --length L [-o OUT.vtp] [--png OUT.png] [--shape NAME]
                   [--sheet-resolution R] [--tolerance T | --step S]
  exactmat revolve [PROFILE] [--angle DEG] [--axis PX,PY,PZ[,DX,DY,DZ]] [-o OUT.vtp]
                   [--png OUT.png] [--shape NAME] [--sheet-resolution R] [...]
  exactmat 3d [SOLID] [-o OUT.vtp] [--tolerance T | --step S [--branch-step B]]
              [--max-step H] [--no-sheets | --sheet-resolution R] [--sheet-fit FIT.vtu]
              [--png OUT.png] [--shape NAME] [--verify-tolerance V]
  exactmat batch FILE|FOLDER... [-o DIR] [-j N] [--mode auto|2d|3d|extrude|revolve]
                 [the options of that mode]
  exactmat shapes          list the bundled shapes

  INPUT          boundary curves: a .vtu of Bezier cells, ExactMAT .json NURBS, or a
                 planar face or wires of a .step/.stp/.iges/.igs file (read exactly);
                 default: the bundled shape plate-with-holes (or --shape NAME)
  --face N       which planar face of a STEP/IGES INPUT (default 0, file order)
  --part N|NAME  which solid (3d) or planar face (2d) of a STEP/IGES INPUT: its index
                 (default 0) or the name the file gives it
  -o OUT.vtp     the MAT as VTK XML polydata (default: exactmat-2d.vtp)
  --tolerance T  adaptive steps: polyline within T x domain size of the MAT (default 1e-4)
  --step S       fixed steps of S x domain size, as in the thesis (branch check every B,
                 default 10 S)
  --png OUT.png  a picture of the boundary and the MAT coloured by radius (--png auto:
                 exactmat-2d.png, exactmat-3d.png, ... after the command)
  --verify-tolerance V  the self-verification's bound on |distance - radius| / size
                 (default 1e-9); a failed verification exits with 3
  -j, --threads N  threads (0, the default: every core; 1: this thread only)
  -h, --help     this text

  exit codes: 0 done and verified, 1 invalid input (or the MAT cannot be computed),
  2 usage error, 3 written but the self-verification failed, 4 output not written

  extrude, revolve: the MAT of the solid swept by the profile PROFILE (2D input as above)
  --length L     extrusion length along the profile plane's normal (needed)
  --angle DEG    revolution angle, (0, 360] (default 360)
  --axis P[,D]   revolution axis through point P along D (default D = 0,1,0); default axis:
                 parallel to y, half the profile's width left of it
  --sheet-resolution R  sheet vertex spacing, fraction of the solid's size (default 0.02)
  OUT.vtp defaults to exactmat-extrude.vtp / exactmat-revolve.vtp

  3d: the MAT of a solid bounded by exact faces — seams, junctions, rims and the medial
  sheets (SOLID: a .vtu of Bezier quadrilaterals/triangles or planar quads/triangles,
  ExactMAT .json surfaces, or a solid of a .step/.stp/.iges/.igs file; default: the
  bundled free-form shape pillow, or --shape NAME). The sheets are triangles
  (vtkSheetInterpolator) within T (--tolerance) of the exact sheets, edges at most R x
  size (--sheet-resolution, default 0.05); every vertex is verified, and the sheets'
  touchpoints must cover every face (exit 3 when a sheet is missing or incomplete).
  --tolerance T  seam polylines (and sheet triangles) within T x solid size (default 1e-4)
  --max-step H   longest step along a seam, fraction of the size (default 0.05)
  --step S       fixed steps of S x solid size along the seams, as in the thesis (junction
                 check every B, default 10 S)
  --no-sheets    the seams, junctions and rims only (the sheets' topology as field data)
  --sheet-fit FIT.vtu  every sheet as a cubic B-spline surface of centre
                 and radius fitted to its exact balls, written as Bezier quadrilaterals
                 (point data Radius, cell data SheetId, SheetFitError), each within T of
                 the sheet's balls (exit 3 when one is not)
  OUT.vtp defaults to exactmat-3d.vtp

  batch: every part file given, and every .vtu/.json/.step/.stp/.iges/.igs file of every
  folder given, through one filter, N parts at a time (-j), with a progress bar. Writes
  DIR/NAME.vtp per part (NAME: the file's name without extension), DIR/index.pvd (open it in
  ParaView: every part as one collection) and DIR/summary.csv (part, file, mode, status,
  segments_or_seams, branch_points_or_junctions, points, seconds, verified_error, message).
  A part that cannot be read or computed is reported by name; the others are computed.
  Solids get their medial sheets, as with 3d (--no-sheets: the seams only).
  --mode M       auto (default: 2d or 3d by the part's cells), 2d, 3d, extrude (needs
                 --length), revolve (needs --axis PX,PY,PZ,DX,DY,DZ)
  DIR defaults to exactmat-batch; exit 1 if a part failed, else 3 if a part's
  verification failed. On a cluster: Wrapping/Python/exactmat/batch.py under
  mpiexec -n N pvbatch --mpi --symmetric (see the README).
)";

struct Arguments
{
  std::string command, input, output, png, shape = "plate-with-holes";
  double tolerance = 1e-4, step = 0.0, branchStep = 0.0, verifyTolerance = 1e-9;
  double length = 0.0, angle = 360.0, sheetResolution = 0.02, maxStep = 0.05;
  bool shapeGiven = false, outputGiven = false;
  bool sheets = true;               ///< 3d: the medial sheets too (vtkSheetInterpolator)
  std::string sheetFit;             ///< 3d --sheets: where to write the sheets' B-spline fits
  bool sheetResolutionGiven = false;
  int part = 0; ///< solid or face of a STEP/IGES input
  std::string partName; ///< or its name in the file
  std::vector<double> axis; ///< empty, or point (3) and optionally direction (3)
  int threads = 0;          ///< -j: 0 every core
  std::vector<std::string> inputs; ///< batch: files and folders
  std::string mode = "auto";       ///< batch: the filter (auto: 2d or 3d by the cells)
};

[[noreturn]] void usageError(const std::string& message)
{
  std::cerr << "exactmat: " << message << "\n" << Usage;
  std::exit(ExitUsage);
}

double number(const std::string& flag, const char* text)
{
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (!text[0] || *end || !(v > 0.0) || !std::isfinite(v))
    usageError(flag + " needs a positive number, got '" + text + "'");
  return v;
}

std::vector<double> numberList(const std::string& flag, const std::string& text)
{
  std::vector<double> v;
  size_t start = 0;
  while (start <= text.size())
  {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string part = text.substr(start, comma - start);
    char* end = nullptr;
    const double x = std::strtod(part.c_str(), &end);
    if (part.empty() || *end || !std::isfinite(x))
      usageError(flag + " needs comma-separated numbers, got '" + text + "'");
    v.push_back(x);
    start = comma + 1;
  }
  if (v.size() != 3 && v.size() != 6)
    usageError(flag + " needs 3 numbers (a point) or 6 (point and direction), got '" + text + "'");
  return v;
}

bool endsWith(const std::string& s, const std::string& suffix);

Arguments parse(int argc, char* argv[])
{
  Arguments a;
  if (argc < 2)
    usageError("no command");
  a.command = argv[1];
  if (a.command == "-h" || a.command == "--help" || a.command == "help")
  {
    std::cout << Usage;
    std::exit(0);
  }
  // `exactmat INPUT [options]`: 2d or 3d by the input's cells (decided in main).
  if (endsWith(a.command, ".vtu") || endsWith(a.command, ".json") ||
    vtkCADBoundaryReader::CanReadFile(a.command.c_str()))
  {
    a.input = a.command;
    a.command = "auto";
  }
  for (int i = 2; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc)
        usageError(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-o" || arg == "--output")
    {
      a.output = value();
      a.outputGiven = true;
    }
    else if (arg == "--png")
      a.png = value();
    else if (arg == "--tolerance")
      a.tolerance = number(arg, value());
    else if (arg == "--step")
      a.step = number(arg, value());
    else if (arg == "--branch-step")
      a.branchStep = number(arg, value());
    else if (arg == "--shape")
    {
      a.shape = value();
      a.shapeGiven = true;
    }
    else if (arg == "--face" || arg == "--part")
    {
      // An index, or (--part) the name the file gives the part.
      const char* text = value();
      char* end = nullptr;
      const long n = std::strtol(text, &end, 10);
      if (text[0] && !*end && n >= 0 && n <= 1000000000)
        a.part = static_cast<int>(n);
      else if (arg == "--part" && text[0] && !std::isdigit(static_cast<unsigned char>(text[0])) && text[0] != '-')
        a.partName = text;
      else
        usageError(arg + " needs an index >= 0" + (arg == "--part" ? std::string(" or a name") : "") + ", got '" +
          text + "'");
    }
    else if (arg == "--max-step")
      a.maxStep = number(arg, value());
    else if (arg == "--length")
      a.length = number(arg, value());
    else if (arg == "--angle")
      a.angle = number(arg, value());
    else if (arg == "--axis")
      a.axis = numberList(arg, value());
    else if (arg == "--verify-tolerance")
      a.verifyTolerance = number(arg, value());
    else if (arg == "--sheet-resolution")
    {
      a.sheetResolution = number(arg, value());
      a.sheetResolutionGiven = true;
    }
    else if (arg == "--sheets")
      a.sheets = true; // (the default; kept for scripts that ask for them)
    else if (arg == "--no-sheets")
      a.sheets = false;
    else if (arg == "--sheet-fit")
      a.sheetFit = value();
    else if (arg == "-j" || arg == "--threads")
    {
      const char* text = value();
      char* end = nullptr;
      const long n = std::strtol(text, &end, 10);
      if (!text[0] || *end || n < 0 || n > 4096)
        usageError(arg + " needs a number of threads (0: every core), got '" + text + "'");
      a.threads = static_cast<int>(n);
    }
    else if (arg == "--mode" && a.command == "batch")
    {
      a.mode = value();
      if (a.mode != "auto" && a.mode != "2d" && a.mode != "3d" && a.mode != "extrude" && a.mode != "revolve")
        usageError("--mode needs auto, 2d, 3d, extrude or revolve, got '" + a.mode + "'");
    }
    else if (arg == "-h" || arg == "--help")
    {
      std::cout << Usage;
      std::exit(0);
    }
    else if (!arg.empty() && arg[0] == '-')
      usageError("unknown option " + arg);
    else if (a.command == "batch")
      a.inputs.push_back(arg);
    else if (a.input.empty())
      a.input = arg;
    else
      usageError("more than one INPUT");
  }
  if (!a.sheetFit.empty() && !a.sheets)
    usageError("--sheet-fit needs the sheets (it fits them): drop --no-sheets");
  if (a.output.empty())
    a.output = a.command == "batch" ? "exactmat-batch" : "exactmat-" + a.command + ".vtp";
  if (a.command == "3d" && !a.shapeGiven)
    a.shape = "pillow"; // the bundled free-form solid
  return a;
}

bool endsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Errors of VTK objects go to stderr as one line each (not VTK's multi-line log).
class ErrorLine : public vtkCommand
{
public:
  static ErrorLine* New() { return new ErrorLine; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    std::string m = data ? static_cast<const char*>(data) : "unknown error";
    const size_t colon = m.find("): ");
    if (colon != std::string::npos)
      m = m.substr(colon + 3);
    while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
      m.pop_back();
    report(m);
  }
  /// An error found by this program (not a VTK object): printed and counted the same way.
  void report(const std::string& m)
  {
    if (!Quiet)
      std::cerr << "exactmat: error: " << m << "\n";
    Message = m;
    Failed = true;
  }
  bool Failed = false;
  std::string Message; ///< the last error
  bool Quiet = false; ///< count the error, the caller words it
};

// Warnings (a failed self-verification) go to stderr as one line each and are remembered.
class WarningLine : public vtkCommand
{
public:
  static WarningLine* New() { return new WarningLine; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    std::string m = data ? static_cast<const char*>(data) : "unknown warning";
    const size_t colon = m.find("): ");
    if (colon != std::string::npos)
      m = m.substr(colon + 3);
    while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
      m.pop_back();
    std::cerr << "exactmat: warning: " << m << "\n";
  }
};

// The 2D MAT settings shared by vtkMAT2DFilter and the profile of vtkMAT25DFilter.
template <typename Filter>
void setProfileSteps(Filter* mat, const Arguments& a)
{
  mat->SetTolerance(a.tolerance);
  mat->SetVerificationTolerance(a.verifyTolerance);
  mat->SetNumberOfThreads(a.threads);
  if (a.step > 0.0)
  {
    mat->FixedStepOn();
    mat->SetStep(a.step);
    mat->SetBranchCheckStep(a.branchStep > 0.0 ? a.branchStep : 10.0 * a.step);
  }
}

// The swept filter from the command line; `axis`: the revolution axis' point and direction.
void configure25D(vtkMAT25DFilter* mat, const Arguments& a, const std::string& command, const double axis[6])
{
  if (command == "revolve")
  {
    mat->SetSweepTypeToRevolution();
    mat->SetAngle(a.angle);
    mat->SetAxisOrigin(axis[0], axis[1], axis[2]);
    mat->SetAxisDirection(axis[3], axis[4], axis[5]);
  }
  else
  {
    mat->SetLength(a.length);
  }
  setProfileSteps(mat, a);
  mat->SetSheetResolution(a.sheetResolution);
}

void configure3D(vtkMAT3DFilter* mat, const Arguments& a)
{
  mat->SetTolerance(a.tolerance);
  mat->SetMaximumStep(a.maxStep);
  if (a.step > 0.0)
  {
    mat->FixedStepOn();
    mat->SetStep(a.step);
    mat->SetJunctionCheckStep(a.branchStep > 0.0 ? a.branchStep : 10.0 * a.step);
  }
  mat->SetVerificationTolerance(a.verifyTolerance);
  mat->SetNumberOfThreads(a.threads);
}

// Any VTK XML writer: binary, its errors (a full disk among them) reported by path.
template <typename Writer>
bool writeXML(vtkDataObject* data, const std::string& path, ErrorLine* errors)
{
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  writer->SetDataModeToBinary();
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  const int written = writer->Write();
  // VTK's XML writer reports a full disk through its error code, not always its result.
  if (written != 1 || errors->Failed || writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    std::cerr << "exactmat: error: cannot write '" << path << "'"
              << (writer->GetErrorCode() == vtkErrorCode::OutOfDiskSpaceError ? ": out of disk space" : "")
              << "\n";
    return false;
  }
  return true;
}

bool writePolyData(vtkPolyData* data, const std::string& path, ErrorLine* errors)
{
  return writeXML<vtkXMLPolyDataWriter>(data, path, errors);
}

// Progress on long runs: a line on stderr every 10% once a second has passed.
class ProgressLine : public vtkCommand
{
public:
  static ProgressLine* New() { return new ProgressLine; }
  void Execute(vtkObject*, unsigned long, void* call) override
  {
    const double f = *static_cast<double*>(call);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - Start).count();
    const int decile = static_cast<int>(f * 10.0);
    if (seconds > 1.0 && decile > LastDecile)
    {
      LastDecile = decile;
      std::cerr << "exactmat: " << What << " " << 10 * decile << "%\n";
    }
  }
  std::string What;
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
  int LastDecile = -1;
};

// Why `path` cannot be a VTK XML unstructured grid, or "" when it may be one: VTK's own
// reader only says "Error parsing input file", which names neither the file nor the cause.
std::string whyNotVTU(const std::string& path)
{
  struct stat info;
  if (stat(path.c_str(), &info) != 0 || access(path.c_str(), R_OK) != 0)
    return "cannot read '" + path + "': " + std::strerror(errno);
  if (S_ISDIR(info.st_mode))
    return "'" + path + "' is a directory, not a .vtu file";
  if (info.st_size == 0)
    return "'" + path + "' is empty";
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f)
    return "cannot read '" + path + "': " + std::strerror(errno);
  std::string head(1024, '\0');
  head.resize(std::fread(&head[0], 1, head.size(), f));
  std::fclose(f);
  if (head.rfind("# vtk DataFile", 0) == 0)
    return "'" + path + "' is a legacy VTK file, not VTK XML: save it as .vtu (e.g. with " +
      "ParaView or vtkXMLUnstructuredGridWriter)";
  const size_t file = head.find("<VTKFile");
  if (file == std::string::npos)
    return "'" + path + "' is not a VTK XML file (no <VTKFile> element at its start)";
  const size_t type = head.find("type=\"", file);
  if (type != std::string::npos && head.compare(type + 6, 17, "UnstructuredGrid\"") != 0)
    return "'" + path + "' is a VTK XML " + head.substr(type + 6, head.find('"', type + 6) - type - 6) +
      " file, not an UnstructuredGrid (.vtu) of boundary curves";
  return "";
}

vtkSmartPointer<vtkUnstructuredGrid> loadBoundary(const Arguments& a, ErrorLine* errors, std::string& label)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  if (a.input.empty())
  {
    auto source = vtkSmartPointer<vtkNURBSSource>::New();
    source->AddObserver(vtkCommand::ErrorEvent, errors);
    if (!source->SetShapeName(a.shape.c_str()))
      return nullptr;
    label = a.shape + " (bundled shape)";
    reader = source;
  }
  else if (endsWith(a.input, ".json"))
  {
    auto r = vtkSmartPointer<vtkNURBSReader>::New();
    r->SetFileName(a.input.c_str());
    reader = r;
    label = a.input;
  }
  else if (vtkCADBoundaryReader::CanReadFile(a.input.c_str()))
  {
    auto r = vtkSmartPointer<vtkCADBoundaryReader>::New();
    r->SetFileName(a.input.c_str());
    r->SetDimension(a.command == "3d" ? 3 : a.command == "auto" ? 0 : 2);
    r->SetPartIndex(a.part);
    if (!a.partName.empty())
      r->SetPartName(a.partName.c_str());
    r->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkNew<WarningLine> warnings;
    if (!errors->Quiet)
      r->AddObserver(vtkCommand::WarningEvent, warnings);
    r->Update();
    if (errors->Failed)
      return nullptr;
    vtkStringArray* name = vtkStringArray::SafeDownCast(r->GetOutput()->GetFieldData()->GetAbstractArray("PartName"));
    // The part's name when it picks one of several (a single part is often named by the
    // exporting program only).
    const std::string partName = name && name->GetNumberOfValues() > 0 &&
        (r->GetNumberOfParts() > 1 || !a.partName.empty()) ? name->GetValue(0) : "";
    label = a.input + (!partName.empty() ? " (part '" + partName + "')" : a.part > 0 ? " (part " + std::to_string(a.part) + ")" : "") +
      ", unit " + (r->GetLengthUnit() ? r->GetLengthUnit() : "?");
    return vtkSmartPointer<vtkUnstructuredGrid>(r->GetOutput());
  }
  else if (endsWith(a.input, ".vtu"))
  {
    const std::string why = whyNotVTU(a.input);
    if (!why.empty())
    {
      errors->report(why);
      return nullptr;
    }
    // VTK's parse errors are replaced by one that names the file.
    vtkNew<ErrorLine> parseErrors;
    parseErrors->Quiet = true;
    vtkNew<vtkXMLUnstructuredGridReader> r;
    r->SetFileName(a.input.c_str());
    r->AddObserver(vtkCommand::ErrorEvent, parseErrors);
    r->Update();
    if (parseErrors->Failed || r->GetErrorCode() != vtkErrorCode::NoError)
    {
      errors->report("'" + a.input + "' is not a readable VTK XML UnstructuredGrid (truncated or corrupt)");
      return nullptr;
    }
    label = a.input;
    return vtkSmartPointer<vtkUnstructuredGrid>(r->GetOutput());
  }
  else
  {
    errors->report("'" + a.input + "' is none of .vtu, .json, .step/.stp, .iges/.igs");
    return nullptr;
  }
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->Update();
  if (errors->Failed)
    return nullptr;
  auto grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
  return grid;
}

// Independent cycles of the medial graph: polylines − nodes + connected components.
int cycleCount(vtkPolyData* mat)
{
  std::vector<vtkIdType> parent(mat->GetNumberOfPoints());
  for (size_t i = 0; i < parent.size(); ++i)
    parent[i] = static_cast<vtkIdType>(i);
  auto find = [&](vtkIdType x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  long long components = mat->GetNumberOfVerts(), lines = 0;
  vtkCellArray* cells = mat->GetLines();
  vtkNew<vtkIdList> ids;
  for (cells->InitTraversal(); cells->GetNextCell(ids); ++lines)
  {
    const vtkIdType a = find(ids->GetId(0)), b = find(ids->GetId(ids->GetNumberOfIds() - 1));
    if (a != b)
    {
      parent[a] = b;
      --components;
    }
  }
  return static_cast<int>(lines - mat->GetNumberOfVerts() + components);
}

int run2D(const Arguments& a)
{
  // Wall times of this program's own steps, printed apart from the filter's.
  auto clock = std::chrono::steady_clock::now;
  auto msSince = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
  };
  auto t0 = clock();
  vtkNew<ErrorLine> errors;
  std::string label;
  vtkSmartPointer<vtkUnstructuredGrid> boundary = loadBoundary(a, errors, label);
  if (!boundary)
    return ExitInputError;
  const double readMs = msSince(t0);

  vtkNew<vtkMAT2DFilter> mat;
  mat->SetInputData(boundary);
  setProfileSteps(mat.GetPointer(), a);
  mat->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<WarningLine> warnings;
  mat->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkNew<ProgressLine> progress;
  progress->What = "tracing";
  mat->AddObserver(vtkCommand::ProgressEvent, progress);
  t0 = clock();
  mat->Update();
  const double filterMs = msSince(t0);
  if (errors->Failed)
    return ExitInputError;
  vtkPolyData* out = mat->GetOutput();
  const exactmat::Boundary2D b = exactmat::buildNormalised(exactmat::curvePiecesFromGrid(boundary));
  vtkDataArray* type = out->GetPointData()->GetArray(exactmat::arrays::PointType);
  int counts[6] = { 0, 0, 0, 0, 0, 0 };
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const int t = static_cast<int>(type->GetTuple1(i));
    if (t >= 0 && t < 6)
      ++counts[t];
  }

  t0 = clock();
  if (!writePolyData(out, a.output, errors))
    return ExitOutputError;
  const double writeMs = msSince(t0);

  const int holes = b.holeCount();
  std::printf("ExactMAT 2D medial axis transform of %s\n", label.c_str());
  std::printf("  boundary            %zu loops (%d holes), %zu Bezier pieces, size %.6g\n",
    b.loops().size(), holes, b.edges().size(), b.userLength(b.diagonal()));
  std::printf("  mode                %s\n",
    a.step > 0 ? ("fixed step " + std::to_string(a.step)).c_str()
               : ("adaptive, tolerance " + std::to_string(a.tolerance)).c_str());
  std::printf("  segments            %d\n", mat->GetNumberOfSegments());
  std::printf("  branch points       %d\n", counts[1]);
  std::printf("  end points          %d (%d at convex vertices, %d at centres of curvature%s)\n",
    counts[2] + counts[3] + counts[5], counts[2], counts[3], counts[5] ? ", 1 circle centre" : "");
  std::printf("  cycles              %d (holes: %d)\n", cycleCount(out), holes);
  std::printf("  points              %lld\n", static_cast<long long>(out->GetNumberOfPoints()));
  std::printf("  time                %.3f ms set-up, %.3f ms tracing, %.3f ms verification\n",
    1e3 * mat->GetSetUpSeconds(), 1e3 * mat->GetTracingSeconds(), 1e3 * mat->GetVerificationSeconds());
  std::printf("  time (VTK, I/O)     %.3f ms output arrays, %.3f ms rest of the filter's pipeline; "
              "%.3f ms reading, %.3f ms writing\n",
    1e3 * mat->GetOutputSeconds(),
    std::max(0.0, filterMs - 1e3 * (mat->GetSetUpSeconds() + mat->GetTracingSeconds() +
      mat->GetOutputSeconds() + mat->GetVerificationSeconds())),
    readMs, writeMs);
  std::printf("  largest verified error  %.3g (|distance to boundary - radius| / size)\n",
    mat->GetMaximumVerifiedError());
  std::printf("  verification        %s\n", mat->GetVerificationPassed() ? "passed" : "FAILED");
  std::printf("  wrote               %s\n", a.output.c_str());

  if (!a.png.empty())
  {
    std::string error;
    auto count = [](int n, const char* noun) {
      return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
    };
    const std::string title = "MAT of " + label + ": " + count(mat->GetNumberOfSegments(), "segment") +
      ", " + count(counts[1], "branch point");
    if (!writeMATPicture(boundary, out, a.png, title, error))
    {
      std::cerr << "exactmat: error: " << error << "\n";
      return ExitOutputError;
    }
    std::printf("  wrote               %s\n", a.png.c_str());
  }
  return mat->GetVerificationPassed() ? 0 : ExitVerification;
}

int run25D(const Arguments& a)
{
  const bool revolve = a.command == "revolve";
  if (!revolve && a.length <= 0.0)
    usageError("extrude needs --length L");
  vtkNew<ErrorLine> errors;
  std::string label;
  vtkSmartPointer<vtkUnstructuredGrid> profile = loadBoundary(a, errors, label);
  if (!profile)
    return ExitInputError;
  double bounds[6];
  profile->GetBounds(bounds);
  double axis[6] = { bounds[0] - 0.5 * (bounds[1] - bounds[0]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]), 0.0, 1.0, 0.0 };
  for (size_t i = 0; i < a.axis.size(); ++i)
    axis[i] = a.axis[i];

  vtkNew<vtkMAT25DFilter> mat;
  mat->SetInputData(profile);
  configure25D(mat, a, a.command, axis);
  mat->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<WarningLine> warnings;
  mat->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkNew<ProgressLine> progress;
  progress->What = "computing";
  mat->AddObserver(vtkCommand::ProgressEvent, progress);
  const auto start = std::chrono::steady_clock::now();
  mat->Update();
  const double totalMs =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (errors->Failed)
    return ExitInputError;
  vtkPolyData* out = mat->GetOutput();

  if (!writePolyData(out, a.output, errors))
    return ExitOutputError;
  const double profileMs = 1e3 * mat->GetProfileSeconds();
  const double buildMs = 1e3 * mat->GetConstructionSeconds();
  char sweep[160];
  if (revolve)
    std::snprintf(sweep, sizeof sweep, "revolved by %g deg about (%g, %g, %g) + t (%g, %g, %g)",
      a.angle, axis[0], axis[1], axis[2], axis[3], axis[4], axis[5]);
  else
    std::snprintf(sweep, sizeof sweep, "extruded by %g", a.length);
  std::printf("ExactMAT 2.5D medial axis transform of %s, %s\n", label.c_str(), sweep);
  std::printf("  junctions           %d\n", mat->GetNumberOfJunctions());
  std::printf("  seams               %d\n", mat->GetNumberOfSeams());
  std::printf("  skeletal edges      %d\n", mat->GetNumberOfSkeletalEdges());
  std::printf("  sheets              %d (%lld triangles)\n", mat->GetNumberOfSheets(),
    static_cast<long long>(out->GetNumberOfPolys()));
  std::printf("  points              %lld\n", static_cast<long long>(out->GetNumberOfPoints()));
  std::printf("  time                %.2f ms profile MAT, %.2f ms 3D construction, %.2f ms verification\n",
    profileMs, buildMs, std::max(0.0, totalMs - profileMs - buildMs));
  std::printf("  verified            %d points: largest |distance to boundary - radius| / size %.3g, "
              "touchpoint mismatches %d\n",
    mat->GetNumberOfVerifiedPoints(), mat->GetMaximumVerifiedError(),
    mat->GetNumberOfTouchpointMismatches());
  std::printf("  verification        %s\n", mat->GetVerificationPassed() ? "passed" : "FAILED");
  std::printf("  wrote               %s\n", a.output.c_str());

  if (!a.png.empty())
  {
    // The solid for the picture: the same profile swept by vtkNURBSSource.
    vtkNew<vtkNURBSSource> solid;
    solid->SetShape(vtkNURBSSource::UserDefined);
    for (const exactmat::CurvePiece& piece : exactmat::curvePiecesFromGrid(profile))
    {
      const exactmat::NurbsCurve c = piece.curve.toNurbs();
      vtkNew<vtkDoubleArray> knots, weights;
      vtkNew<vtkPoints> points;
      for (double k : c.knots())
        knots->InsertNextValue(k);
      for (int i = 0; i < c.controlPointCount(); ++i)
      {
        points->InsertNextPoint(c.controlPoint(i).data());
        weights->InsertNextValue(c.weight(i));
      }
      solid->AddCurve(c.degree(), knots, points, weights);
    }
    solid->SetSweep(revolve ? vtkNURBSSource::SweepRevolution : vtkNURBSSource::SweepExtrusion);
    solid->SetLength(a.length);
    solid->SetSweepAngle(a.angle);
    solid->SetSweepAxisOrigin(axis);
    solid->SetSweepAxisDirection(axis + 3);
    solid->AddObserver(vtkCommand::ErrorEvent, errors);
    solid->Update();
    if (errors->Failed)
      return ExitInputError;
    std::string error;
    const std::string title = "MAT of " + label + " " + (revolve ? "revolved" : "extruded") + ": " +
      std::to_string(mat->GetNumberOfJunctions()) + " junctions, " +
      std::to_string(mat->GetNumberOfSeams()) + " seams, " +
      std::to_string(mat->GetNumberOfSheets()) + " sheets";
    if (!writeSolidMATPicture(solid->GetOutput(), out, a.png, title, error))
    {
      std::cerr << "exactmat: error: " << error << "\n";
      return ExitOutputError;
    }
    std::printf("  wrote               %s\n", a.png.c_str());
  }
  return mat->GetVerificationPassed() ? 0 : ExitVerification;
}
int run3D(const Arguments& a)
{
  vtkNew<ErrorLine> errors;
  std::string label;
  vtkSmartPointer<vtkUnstructuredGrid> solid = loadBoundary(a, errors, label);
  if (!solid)
    return ExitInputError;
  vtkNew<vtkMAT3DFilter> mat;
  mat->SetInputData(solid);
  configure3D(mat, a);
  mat->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<WarningLine> warnings;
  mat->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkNew<ProgressLine> progress;
  progress->What = "tracing seams";
  mat->AddObserver(vtkCommand::ProgressEvent, progress);
  mat->Update();
  if (errors->Failed)
    return ExitInputError;
  vtkPolyData* out = mat->GetOutput();
  vtkNew<vtkSheetInterpolator> sheets;
  if (a.sheets)
  {
    sheets->SetInputConnection(mat->GetOutputPort());
    sheets->SetSourceData(solid);
    sheets->SetTolerance(a.tolerance);
    if (a.sheetResolutionGiven)
      sheets->SetMaximumEdgeLength(a.sheetResolution);
    sheets->SetVerificationTolerance(mat->GetVerificationTolerance());
    sheets->SetNumberOfThreads(a.threads);
    sheets->SetFitSheets(!a.sheetFit.empty());
    sheets->AddObserver(vtkCommand::ErrorEvent, errors);
    sheets->AddObserver(vtkCommand::WarningEvent, warnings);
    vtkNew<ProgressLine> sheetProgress;
    sheetProgress->What = "filling sheets";
    sheets->AddObserver(vtkCommand::ProgressEvent, sheetProgress);
    sheets->Update();
    if (errors->Failed)
      return ExitInputError;
    out = sheets->GetOutput();
  }
  if (!writePolyData(out, a.output, errors))
    return ExitOutputError;
  const bool fitted = a.sheets && !a.sheetFit.empty();
  if (fitted && !writeXML<vtkXMLUnstructuredGridWriter>(sheets->GetOutputDataObject(1), a.sheetFit, errors))
    return ExitOutputError;
  const bool passed = mat->GetVerificationPassed() && (!a.sheets || sheets->GetVerificationPassed()) &&
    (!fitted || sheets->GetNumberOfSheetsAboveFitTolerance() == 0);
  const exactmat::Boundary3D b = exactmat::buildNormalised(exactmat::patchPiecesFromGrid(solid));
  std::printf("ExactMAT 3D medial axis transform (seams and junctions) of %s\n", label.c_str());
  std::printf("  boundary            %zu faces, %d convex / %d reflex / %d smooth edges, %d convex / %d reflex "
              "vertices, size %.6g\n",
    b.faces().size(), b.countEdges(exactmat::VertexKind::Convex), b.countEdges(exactmat::VertexKind::Reflex),
    b.countEdges(exactmat::VertexKind::Smooth), b.countVertices(exactmat::VertexKind::Convex),
    b.countVertices(exactmat::VertexKind::Reflex), b.userFrame().lengthToUser(b.diagonal()));
  std::printf("  junctions           %d\n", mat->GetNumberOfJunctions());
  std::printf("  seams               %d\n", mat->GetNumberOfSeams());
  std::printf("  skeletal edges      %d (rims: where sheets end inside the solid)\n", mat->GetNumberOfSkeletalEdges());
  std::printf("  centre curves       %d (axes: balls touching a whole circle)\n", mat->GetNumberOfCentreCurves());
  if (mat->GetNumberOfSphereCentres() > 0)
    std::printf("  sphere centre       %d (the solid is a ball: its MAT is the centre, touching every face)\n",
      mat->GetNumberOfSphereCentres());
  if (!a.sheets)
    std::printf("  sheets              %d (generator pairs and their bounding seams; not filled: --no-sheets)\n",
      mat->GetNumberOfSheets());
  else
    std::printf("  sheets              %d filled (%d failed), %d triangles, within %.3g of the exact sheets\n",
      sheets->GetNumberOfInterpolatedSheets(), sheets->GetNumberOfFailedSheets(), sheets->GetNumberOfTriangles(),
      sheets->GetMaximumDeviation());
  std::printf("  points              %lld\n", static_cast<long long>(out->GetNumberOfPoints()));
  std::printf("  time                %.2f ms tracing, %.2f ms verification\n", 1e3 * mat->GetTracingSeconds(),
    1e3 * mat->GetVerificationSeconds());
  std::printf("  verified            %d points: largest |distance to boundary - radius| / size %.3g, "
              "touchpoint mismatches %d\n",
    mat->GetNumberOfVerifiedPoints(), mat->GetMaximumVerifiedError(), mat->GetNumberOfTouchpointMismatches());
  if (mat->GetNumberOfWitnessedPoints() > 0)
    std::printf("  verified by witness %d points (their touchpoint search ran out of boxes: distance proved by the "
                "recorded touch and the shrunk ball's emptiness; touch count not re-counted)\n",
      mat->GetNumberOfWitnessedPoints());
  if (a.sheets)
  {
    std::printf("  sheets time         %.2f ms filling, %.2f ms verification\n",
      1e3 * sheets->GetInterpolationSeconds(), 1e3 * sheets->GetVerificationSeconds());
    std::printf("  sheets verified     %d points: largest |distance to boundary - radius| / size %.3g, "
                "touchpoint mismatches %d; faces covered by the sheets' touchpoints to %.3g\n",
      sheets->GetNumberOfVerifiedPoints(), sheets->GetMaximumVerifiedError(),
      sheets->GetNumberOfTouchpointMismatches(), sheets->GetMaximumCoverageShortfall());
  }
  if (fitted)
    std::printf("  sheet fits          %d Bezier patches in %.2f ms, largest error / size %.3g at the sheets' "
                "exact balls (%d sheet(s) above the tolerance)\n",
      sheets->GetNumberOfFitPatches(), 1e3 * sheets->GetFitSeconds(), sheets->GetMaximumFitError(),
      sheets->GetNumberOfSheetsAboveFitTolerance());
  std::printf("  verification        %s\n", passed ? "passed" : "FAILED");
  std::printf("  wrote               %s\n", a.output.c_str());
  if (fitted)
    std::printf("  wrote               %s\n", a.sheetFit.c_str());
  if (!a.png.empty())
  {
    std::string error;
    auto count = [](int n, const char* noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); };
    const std::string title = "MAT of " + label + ": " + count(mat->GetNumberOfJunctions(), "junction") + ", " +
      count(mat->GetNumberOfSeams(), "seam") +
      (mat->GetNumberOfSkeletalEdges() > 0 ? ", " + count(mat->GetNumberOfSkeletalEdges(), "rim") : std::string()) +
      (mat->GetNumberOfCentreCurves() > 0 ? ", " + count(mat->GetNumberOfCentreCurves(), "centre curve") : std::string()) +
      (mat->GetNumberOfSphereCentres() > 0 ? std::string(", the ball's centre") : std::string()) +
      (a.sheets ? ", " + count(sheets->GetNumberOfInterpolatedSheets(), "sheet") : std::string(" (sheets not filled)"));
    if (!writeSolidMATPicture(solid, out, a.png, title, error))
    {
      std::cerr << "exactmat: error: " << error << "\n";
      return ExitOutputError;
    }
    std::printf("  wrote               %s\n", a.png.c_str());
  }
  return passed ? 0 : ExitVerification;
}
int runBatch(const Arguments& a)
{
  if (a.inputs.empty())
    usageError("batch needs part files or folders");
  if (a.mode == "extrude" && a.length <= 0.0)
    usageError("batch --mode extrude needs --length L");
  if (a.mode == "revolve" && a.axis.size() != 6)
    usageError("batch --mode revolve needs --axis PX,PY,PZ,DX,DY,DZ (one axis for every part)");
  exactmat::BatchJob job;
  job.inputs = a.inputs;
  job.outputDir = a.output;
  job.mode = a.mode;
  job.threads = a.threads;
  job.load = [&a](const std::string& file, const std::string& mode, std::string& error) {
    Arguments one = a;
    one.input = file;
    one.command = mode == "extrude" || mode == "revolve" ? "2d" : mode;
    vtkNew<ErrorLine> errors;
    errors->Quiet = true;
    std::string label;
    vtkSmartPointer<vtkUnstructuredGrid> grid = loadBoundary(one, errors, label);
    if (!grid || errors->Failed)
    {
      error = errors->Message.empty() ? "cannot be read" : errors->Message;
      return vtkSmartPointer<vtkUnstructuredGrid>();
    }
    return grid;
  };
  job.makeFilter = [&a](const std::string& mode) -> vtkSmartPointer<vtkMATAlgorithm> {
    if (mode == "3d")
    {
      auto f = vtkSmartPointer<vtkMAT3DFilter>::New();
      configure3D(f, a);
      return f;
    }
    if (mode == "extrude" || mode == "revolve")
    {
      auto f = vtkSmartPointer<vtkMAT25DFilter>::New();
      double axis[6] = { 0, 0, 0, 0, 1, 0 };
      for (size_t i = 0; i < a.axis.size() && i < 6; ++i)
        axis[i] = a.axis[i];
      configure25D(f, a, mode, axis);
      return f;
    }
    auto f = vtkSmartPointer<vtkMAT2DFilter>::New();
    setProfileSteps(f.GetPointer(), a);
    return f;
  };
  // 3d parts get their sheets, as `exactmat 3d` does (unless --no-sheets).
  if (a.sheets)
    job.finish = [&a](const std::string& mode, vtkPolyData* mat, vtkUnstructuredGrid* boundary, std::string& error,
                   bool& verified) -> vtkSmartPointer<vtkPolyData> {
      if (mode != "3d")
        return mat;
      vtkNew<vtkSheetInterpolator> sheets;
      sheets->SetInputData(mat);
      sheets->SetSourceData(boundary);
      sheets->SetTolerance(a.tolerance);
      if (a.sheetResolutionGiven)
        sheets->SetMaximumEdgeLength(a.sheetResolution);
      sheets->SetNumberOfThreads(a.threads);
      sheets->SetFitSheets(false);
      vtkNew<ErrorLine> errors;
      errors->Quiet = true;
      vtkNew<vtkCallbackCommand> quiet;
      sheets->AddObserver(vtkCommand::ErrorEvent, errors);
      sheets->AddObserver(vtkCommand::WarningEvent, quiet);
      sheets->Update();
      if (errors->Failed)
      {
        error = "sheets: " + errors->Message;
        return nullptr;
      }
      verified = sheets->GetVerificationPassed();
      if (!verified)
        error = "sheets: verification failed (" + std::to_string(sheets->GetNumberOfFailedSheets()) +
          " sheet(s) not filled, faces covered to " + std::to_string(sheets->GetMaximumCoverageShortfall()) + ")";
      vtkSmartPointer<vtkPolyData> out = sheets->GetOutput();
      return out;
    };
  return exactmat::runBatch(job);
}
} // namespace

int main(int argc, char* argv[])
{
  // Errors reach the user through ErrorLine observers, one line each; the pipeline's own
  // multi-line log would repeat them.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  const Arguments a = parse(argc, argv);
  if (a.command == "shapes")
  {
    for (int i = 0; i < vtkNURBSSource::GetNumberOfCatalogueShapes(); ++i)
      std::cout << vtkNURBSSource::GetCatalogueShapeName(i) << "\n";
    return 0;
  }
  if (a.command == "batch")
    return runBatch(a);
  if (a.command != "2d" && a.command != "3d" && a.command != "extrude" && a.command != "revolve" &&
    a.command != "auto")
    usageError("unknown command '" + a.command + "' (this version has: 2d, 3d, extrude, revolve, batch, shapes; or give " +
      "a .vtu, .json, .step or .iges INPUT first)");
  Arguments chosen = a;
  if (a.command == "auto")
  {
    // Faces make a solid (3d), curves a planar domain (2d).
    vtkNew<ErrorLine> errors;
    std::string label;
    const vtkSmartPointer<vtkUnstructuredGrid> boundary = loadBoundary(a, errors, label);
    if (!boundary)
      return ExitInputError;
    chosen.command = exactmat::gridHasSurfaceCells(boundary) ? "3d" : "2d";
    if (!a.outputGiven)
      chosen.output = "exactmat-" + chosen.command + ".vtp";
  }
  if (chosen.png == "auto")
    chosen.png = "exactmat-" + chosen.command + ".png";
  // Off-screen rendering with this VTK needs an X display: run under Xvfb when none is set.
  const char* display = std::getenv("DISPLAY");
  if (!a.png.empty() && (!display || !*display) && !std::getenv("EXACTMAT_NO_XVFB"))
  {
    setenv("EXACTMAT_NO_XVFB", "1", 1);
    std::vector<char*> args{ const_cast<char*>("xvfb-run"), const_cast<char*>("-a"),
      const_cast<char*>("-s"), const_cast<char*>("-screen 0 1280x1024x24") };
    for (int i = 0; i < argc; ++i)
      args.push_back(argv[i]);
    args.push_back(nullptr);
    execvp("xvfb-run", args.data());
    std::cerr << "exactmat: --png needs an X display and xvfb-run was not found (apt-get install xvfb)\n";
    return 1;
  }
  try
  {
    return chosen.command == "2d" ? run2D(chosen) : chosen.command == "3d" ? run3D(chosen) : run25D(chosen);
  }
  catch (const exactmat::InputError& e)
  {
    std::cerr << "exactmat: error: " << e.what() << "\n";
    return ExitInputError;
  }
}
