/**
 * @class   vtkMATAlgorithm
 * @brief   What every MAT filter shares: one boundary or a collection of them in, threads,
 *          self-verification, and the report of each part's figures and failures.
 *
 * Input: one boundary as a vtkUnstructuredGrid, or a composite dataset of them (a
 * vtkPartitionedDataSetCollection, one part per partitioned dataset, or a
 * vtkMultiBlockDataSet, one part per leaf). A single boundary gives vtkPolyData; a
 * collection gives the same structure with each part's MAT in its place (a part that
 * fails gets an empty vtkPolyData; the others are computed regardless).
 *
 * Every part's output carries its figures as field data (the subclass's counts and times,
 * `NumberOfSegments`, `TracingSeconds`, …) and its verification (`VerificationStatus`,
 * `MaximumVerifiedError`, `VerificationReport`). A collection's output also carries a
 * summary, one row per part in input order, as field data: `PartName` (the collection's
 * NAME metadata, else "part N"), `PartStatus` (0 verified, 1 computed but not verified,
 * 2 verification failed, 3 failed: no MAT), `PartMessage` (the error or the verification
 * report), `PartSeconds`, `MaximumVerifiedError` and every figure. A failed part is also
 * named in a warning. The getters then hold the sums of the figures over the parts, the
 * largest verified error, and whether every part passed.
 *
 * Threads (vtkSMPTools, STDThread backend, NumberOfThreads): a collection's parts run
 * concurrently, one part per thread; a single part's verification runs its points
 * concurrently. Results are identical to one thread, bit for bit: each part is computed
 * by the same sequential code and the verification reduces its points in order.
 *
 * Distributed (the pipeline asks for one piece of several, as ParaView does over pvserver
 * or pvbatch ranks): each rank computes the parts it holds (an empty leaf is another
 * rank's), the summary rows are gathered over the global MPI controller, and every rank's
 * summary and getters then describe the whole collection. A single boundary is computed
 * where it is (piece 0 for the project's sources and readers); the other ranks output
 * nothing.
 */
#ifndef vtkMATAlgorithm_h
#define vtkMATAlgorithm_h

#include "ExactMATFiltersMedialModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <functional> // for the part's progress callback

class vtkUnstructuredGrid;
namespace exactmat
{
struct PartResult;
}

class EXACTMATFILTERSMEDIAL_EXPORT vtkMATAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkMATAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Threads used (vtkSMPTools' STDThread backend, whatever backend VTK defaults to):
   * 0 = every core (or VTK_SMP_MAX_THREADS when set; the default), 1 = the calling thread.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * Self-verification against the exact boundary (default on), and its bound on
   * |distance to the exact boundary − Radius| / size (default 1e-9). When a check fails
   * the filter warns, naming the worst point, VerificationPassed is false and the output's
   * field data say so (`VerificationStatus` 0, `VerificationReport`); the output is still
   * produced. MaximumVerifiedError: the largest such error over the checked points.
   */
  vtkSetMacro(VerifyOutput, bool);
  vtkGetMacro(VerifyOutput, bool);
  vtkBooleanMacro(VerifyOutput, bool);
  vtkSetMacro(VerificationTolerance, double);
  vtkGetMacro(VerificationTolerance, double);
  vtkGetMacro(VerificationPassed, bool);
  vtkGetMacro(MaximumVerifiedError, double);
  ///@}

  ///@{
  /// A collection's parts in the last run, and how many of them failed (an error, or
  /// verification failed). 1 and 0 or 1 for a single boundary.
  vtkGetMacro(NumberOfParts, int);
  vtkGetMacro(NumberOfFailedParts, int);
  ///@}

protected:
  vtkMATAlgorithm();
  ~vtkMATAlgorithm() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo) override;
  virtual int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The MAT of one boundary into `output`, its figures and verification outcome into
   * `result`. Throws exactmat::InputError on bad input (its message names the cell, the
   * parameter or the problem). May run on a worker thread, several parts at once: reads the
   * filter's parameters, writes nothing else of the filter. `parallel` runs independent
   * per-point work; `progress` takes fractions in [0, 1].
   */
  virtual void ComputePart(vtkUnstructuredGrid* input, vtkPolyData* output,
    exactmat::PartResult& result, const std::function<void(double)>& progress) const = 0;

  /// Copies the figures of the last run (one part's, or the sums over a collection's) to
  /// the subclass's getters.
  virtual void PublishFigures(const exactmat::PartResult& figures) = 0;

  int NumberOfThreads = 0;
  bool VerifyOutput = true;
  double VerificationTolerance = 1e-9;
  bool VerificationPassed = true;
  double MaximumVerifiedError = 0.0;
  int NumberOfParts = 0;
  int NumberOfFailedParts = 0;

private:
  vtkMATAlgorithm(const vtkMATAlgorithm&) = delete;
  void operator=(const vtkMATAlgorithm&) = delete;
};

#endif
