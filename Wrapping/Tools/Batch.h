#pragma once
// `exactmat batch`: many parts through one MAT filter as a collection (vtkMATAlgorithm's
// composite input), on this machine's threads, with a progress bar; one .vtp per part, a
// ParaView collection index and a CSV summary. The MPI variant for clusters is
// Wrapping/Python/exactmat/batch.py (pvbatch), which writes the same files.

#include "vtkMATAlgorithm.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <functional>
#include <string>
#include <vector>

namespace exactmat
{

struct BatchJob
{
  std::vector<std::string> inputs; ///< part files, or folders (their part files, sorted)
  std::string outputDir;
  std::string mode = "auto"; ///< auto (2d or 3d by the part's cells), 2d, extrude, revolve, 3d
  int threads = 0;           ///< 0: every core
  /// Reads one part file for `mode` ("2d", "3d", ... or "auto"); null and `error` set when
  /// it cannot.
  std::function<vtkSmartPointer<vtkUnstructuredGrid>(
    const std::string& file, const std::string& mode, std::string& error)>
    load;
  /// The filter for a mode ("2d", "extrude", "revolve", "3d"), configured from the command line.
  std::function<vtkSmartPointer<vtkMATAlgorithm>(const std::string& mode)> makeFilter;
  /// Optional, per part after its filter (for "3d": the medial sheets): the part's final
  /// output from its MAT and boundary, or null with `error` set; `verified` false when the
  /// step's own verification failed.
  std::function<vtkSmartPointer<vtkPolyData>(const std::string& mode, vtkPolyData* mat,
    vtkUnstructuredGrid* boundary, std::string& error, bool& verified)>
    finish;
};

/// The files a batch reads: every input file, and the part files (.vtu, .json, .step,
/// .stp, .iges, .igs) of every input folder, sorted by name.
std::vector<std::string> batchFiles(const std::vector<std::string>& inputs, std::string& error);

/// Runs the job; returns the exit code: 0 every part verified, 3 some part's verification
/// failed, 1 some part could not be read or computed (the others are written), 4 an output
/// could not be written.
int runBatch(const BatchJob& job);

} // namespace exactmat
