#include "Batch.h"

#include "vtkExactMATArrayNames.h"
#include "vtkMATBoundaryConversion.h"
#include "vtkMATThreads.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPartitionedDataSetCollection.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <unistd.h>

namespace exactmat
{

namespace
{
namespace fs = std::filesystem;

// Parts per collection handed to the filter at once: bounds the memory of a run over
// thousands of parts (each collection's outputs are written and dropped before the next).
constexpr size_t PartsPerRound = 64;

bool isPartFile(const fs::path& p)
{
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".vtu" || ext == ".json" || ext == ".step" || ext == ".stp" || ext == ".iges" ||
    ext == ".igs";
}

// One row of summary.csv.
struct Row
{
  std::string part, file, mode, status, message;
  int curves = 0, nodes = 0;
  long long points = 0;
  double seconds = 0.0, error = 0.0;
};

const char* statusWord(int status)
{
  switch (status)
  {
    case 0:
      return "verified";
    case 1:
      return "not verified";
    case 2:
      return "verification failed";
    default:
      return "failed";
  }
}

std::string csvField(const std::string& s)
{
  if (s.find_first_of(",\"\n") == std::string::npos)
    return s;
  std::string out = "\"";
  for (char c : s)
    out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return out + "\"";
}

std::string xmlAttribute(const std::string& s)
{
  std::string out;
  for (char c : s)
    out += c == '&' ? "&amp;" : c == '"' ? "&quot;" : c == '<' ? "&lt;" : std::string(1, c);
  return out;
}

// Part names from file names: the stem, made unique, safe as a file name.
std::vector<std::string> partNames(const std::vector<std::string>& files)
{
  std::vector<std::string> names;
  std::set<std::string> used;
  for (const std::string& f : files)
  {
    std::string stem = fs::path(f).stem().string();
    for (char& c : stem)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'))
        c = '_';
    std::string name = stem.empty() ? "part" : stem;
    for (int k = 2; used.count(name); ++k)
      name = stem + "-" + std::to_string(k);
    used.insert(name);
    names.push_back(name);
  }
  return names;
}

// A progress bar on a terminal, a line per 10 % otherwise.
class ProgressBar
{
public:
  explicit ProgressBar(size_t total)
    : Total(total)
    , Terminal(isatty(STDERR_FILENO))
  {
  }
  void show(double done)
  {
    const double f = Total ? std::min(1.0, done / static_cast<double>(Total)) : 1.0;
    if (Terminal)
    {
      const int width = 30, filled = static_cast<int>(f * width);
      std::fprintf(stderr, "\rexactmat batch: [%s%s] %5.1f%% (%.0f/%zu parts)",
        std::string(filled, '=').c_str(), std::string(width - filled, ' ').c_str(), 100.0 * f,
        std::floor(done), Total);
      std::fflush(stderr);
    }
    else if (static_cast<int>(f * 10.0) > LastDecile)
    {
      LastDecile = static_cast<int>(f * 10.0);
      std::fprintf(stderr, "exactmat batch: %d%% (%.0f/%zu parts)\n", 10 * LastDecile, std::floor(done), Total);
    }
  }
  void finish()
  {
    if (Terminal)
      std::fprintf(stderr, "\n");
  }

private:
  size_t Total;
  bool Terminal;
  int LastDecile = -1;
};

int intFigure(vtkFieldData* fd, const char* name, vtkIdType row)
{
  vtkDataArray* a = fd->GetArray(name);
  return a && row < a->GetNumberOfTuples() ? static_cast<int>(a->GetTuple1(row)) : 0;
}
} // namespace

std::vector<std::string> batchFiles(const std::vector<std::string>& inputs, std::string& error)
{
  std::vector<std::string> files;
  for (const std::string& in : inputs)
  {
    std::error_code ec;
    if (fs::is_directory(in, ec))
    {
      std::vector<std::string> found;
      for (const fs::directory_entry& e : fs::directory_iterator(in, ec))
        if (e.is_regular_file() && isPartFile(e.path()))
          found.push_back(e.path().string());
      std::sort(found.begin(), found.end());
      if (found.empty())
      {
        error = "folder '" + in + "' holds no .vtu, .json, .step/.stp or .iges/.igs file";
        return {};
      }
      files.insert(files.end(), found.begin(), found.end());
    }
    else
      files.push_back(in); // a missing or bad file is that part's failure, not the batch's
  }
  return files;
}

int runBatch(const BatchJob& job)
{
  std::string error;
  const std::vector<std::string> files = batchFiles(job.inputs, error);
  if (!error.empty())
  {
    std::cerr << "exactmat: error: " << error << "\n";
    return 1;
  }
  std::error_code ec;
  fs::create_directories(job.outputDir, ec);
  if (!fs::is_directory(job.outputDir))
  {
    std::cerr << "exactmat: error: cannot create the output folder '" << job.outputDir << "'\n";
    return 4;
  }
  const std::vector<std::string> names = partNames(files);
  std::vector<Row> rows(files.size());
  ProgressBar bar(files.size());
  bar.show(0);
  bool writeFailed = false;
  const auto start = std::chrono::steady_clock::now();

  for (size_t first = 0; first < files.size(); first += PartsPerRound)
  {
    const size_t last = std::min(files.size(), first + PartsPerRound);
    // Read this round's parts, grouped by the filter they need.
    std::map<std::string, std::vector<size_t>> byMode;
    std::map<size_t, vtkSmartPointer<vtkUnstructuredGrid>> boundaries;
    for (size_t i = first; i < last; ++i)
    {
      Row& row = rows[i];
      row.part = names[i];
      row.file = files[i];
      std::string why;
      const auto t0 = std::chrono::steady_clock::now();
      vtkSmartPointer<vtkUnstructuredGrid> grid = job.load(files[i], job.mode, why);
      row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      row.mode = job.mode;
      if (!grid)
      {
        row.status = statusWord(3);
        row.message = why.empty() ? "cannot be read" : why;
        continue;
      }
      if (row.mode == "auto")
        row.mode = gridHasSurfaceCells(grid) ? "3d" : "2d";
      boundaries[i] = grid;
      byMode[row.mode].push_back(i);
    }
    for (const auto& [mode, indices] : byMode)
    {
      vtkSmartPointer<vtkMATAlgorithm> filter = job.makeFilter(mode);
      vtkNew<vtkPartitionedDataSetCollection> collection;
      for (unsigned int k = 0; k < indices.size(); ++k)
      {
        collection->SetPartition(k, 0, boundaries[indices[k]]);
        collection->GetMetaData(k)->Set(vtkCompositeDataSet::NAME(), names[indices[k]].c_str());
      }
      filter->SetInputDataObject(collection);
      filter->SetNumberOfThreads(job.threads);
      // Failed parts are in the summary; VTK's own messages would repeat them.
      vtkNew<vtkCallbackCommand> quiet;
      filter->AddObserver(vtkCommand::WarningEvent, quiet);
      filter->AddObserver(vtkCommand::ErrorEvent, quiet);
      // Parts done before this group: earlier rounds, this round's unreadable parts, and
      // the groups of other modes already run.
      size_t before = first + (last - first) - boundaries.size();
      for (const auto& [m, ids] : byMode)
      {
        if (m == mode)
          break;
        before += ids.size();
      }
      vtkNew<vtkCallbackCommand> progress;
      struct ProgressState
      {
        ProgressBar* bar;
        double offset, parts;
      } state{ &bar, static_cast<double>(before), static_cast<double>(indices.size()) };
      progress->SetClientData(&state);
      progress->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
        auto* s = static_cast<ProgressState*>(client);
        s->bar->show(s->offset + s->parts * *static_cast<double*>(call));
      });
      filter->AddObserver(vtkCommand::ProgressEvent, progress);
      filter->Update();
      auto* out = vtkPartitionedDataSetCollection::SafeDownCast(filter->GetOutputDataObject(0));
      struct PartFile
      {
        vtkPolyData* mat;
        std::string path;
        size_t row;
        bool failed;
      };
      std::vector<PartFile> writes;
      std::vector<vtkSmartPointer<vtkPolyData>> finished; // (kept alive until written)
      for (unsigned int k = 0; k < indices.size(); ++k)
      {
        Row& row = rows[indices[k]];
        if (!out || k >= out->GetNumberOfPartitionedDataSets())
        {
          row.status = statusWord(3);
          row.message = "the filter gave no output";
          continue;
        }
        vtkFieldData* fd = out->GetFieldData();
        const int status = intFigure(fd, arrays::PartStatus, k);
        row.status = statusWord(status);
        auto* messages = vtkStringArray::SafeDownCast(fd->GetAbstractArray(arrays::PartMessage));
        row.message = messages ? messages->GetValue(k) : "";
        vtkDataArray* seconds = fd->GetArray(arrays::PartSeconds);
        row.seconds += seconds ? seconds->GetTuple1(k) : 0.0;
        vtkDataArray* errors = fd->GetArray(arrays::MaximumVerifiedError);
        row.error = errors ? errors->GetTuple1(k) : 0.0;
        const bool planar = mode == "2d";
        row.curves = intFigure(fd, planar ? "NumberOfSegments" : "NumberOfSeams", k);
        row.nodes = intFigure(fd, planar ? "NumberOfBranchPoints" : "NumberOfJunctions", k);
        auto* mat = vtkPolyData::SafeDownCast(out->GetPartitionAsDataObject(k, 0));
        row.points = mat ? mat->GetNumberOfPoints() : 0;
        if (status == 3 || !mat)
          continue;
        if (job.finish)
        {
          std::string why;
          bool verified = true;
          const auto t0 = std::chrono::steady_clock::now();
          vtkSmartPointer<vtkPolyData> done = job.finish(mode, mat, boundaries[indices[k]], why, verified);
          row.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          if (!done)
          {
            row.status = statusWord(3);
            row.message = why;
            continue;
          }
          if (!verified && status == 0)
          {
            row.status = statusWord(2);
            row.message = why;
          }
          finished.push_back(done);
          mat = done;
          row.points = mat->GetNumberOfPoints();
        }
        writes.push_back({ mat, (fs::path(job.outputDir) / (names[indices[k]] + ".vtp")).string(),
          indices[k], false });
      }
      // The parts' files, written concurrently (each writer compresses its own part).
      withThreads(job.threads, [&writes]() {
        vtkSMPTools::For(vtkIdType(0), static_cast<vtkIdType>(writes.size()), vtkIdType(1),
          [&writes](vtkIdType b, vtkIdType e) {
            for (vtkIdType w = b; w < e; ++w)
            {
              vtkNew<vtkXMLPolyDataWriter> writer;
              writer->SetInputData(writes[w].mat);
              writer->SetFileName(writes[w].path.c_str());
              writer->SetDataModeToBinary();
              vtkNew<vtkCallbackCommand> silent; // the row says it
              writer->AddObserver(vtkCommand::ErrorEvent, silent);
              writes[w].failed =
                writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError;
            }
          });
      });
      for (const PartFile& w : writes)
        if (w.failed)
        {
          rows[w.row].status = statusWord(3);
          rows[w.row].message = "cannot write '" + w.path + "'";
          writeFailed = true;
        }
    }
    bar.show(static_cast<double>(last));
  }
  bar.finish();

  // The summary, and an index ParaView opens as one collection (File > Open index.pvd).
  const fs::path csvPath = fs::path(job.outputDir) / "summary.csv";
  const fs::path indexPath = fs::path(job.outputDir) / "index.pvd";
  std::ofstream csv(csvPath), index(indexPath);
  csv << "part,file,mode,status,segments_or_seams,branch_points_or_junctions,points,seconds,"
         "verified_error,message\n";
  index << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  int failed = 0, unverified = 0, k = 0;
  for (const Row& r : rows)
  {
    char numbers[128];
    std::snprintf(numbers, sizeof numbers, "%d,%d,%lld,%.6g,%.3g", r.curves, r.nodes, r.points,
      r.seconds, r.error);
    csv << csvField(r.part) << "," << csvField(r.file) << "," << r.mode << "," << r.status << ","
        << numbers << "," << csvField(r.message) << "\n";
    if (r.status == statusWord(3))
      ++failed;
    else
      index << "    <DataSet part=\"" << k++ << "\" name=\"" << xmlAttribute(r.part) << "\" file=\""
            << xmlAttribute(r.part) << ".vtp\"/>\n";
    if (r.status == statusWord(2))
      ++unverified;
  }
  index << "  </Collection>\n</VTKFile>\n";
  csv.close();
  index.close();
  if (!csv || !index)
  {
    std::cerr << "exactmat: error: cannot write " << csvPath << " or " << indexPath << "\n";
    return 4;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("ExactMAT batch: %zu parts in %.2f s (%.2f parts/s), %zu verified, %d verification "
              "failed, %d failed\n",
    rows.size(), seconds, rows.size() / std::max(seconds, 1e-9),
    rows.size() - static_cast<size_t>(failed + unverified), unverified, failed);
  for (const Row& r : rows)
    if (r.status == statusWord(3) || r.status == statusWord(2))
      std::printf("  %s (%s): %s: %s\n", r.part.c_str(), r.file.c_str(), r.status.c_str(),
        r.message.c_str());
  std::printf("  wrote               %s, %s and one .vtp per part\n", csvPath.string().c_str(),
    indexPath.string().c_str());
  if (writeFailed)
    return 4;
  return failed ? 1 : unverified ? 3 : 0;
}

} // namespace exactmat
