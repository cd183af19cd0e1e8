#include "vtkMATVerificationReport.h"

#include "vtkExactMATArrayNames.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkStringArray.h>

namespace exactmat
{

VerificationOutcome outcomeOf(const MedialVerification& v, double tolerance, const MedialComplex& mat,
  const Normalisation& frame)
{
  VerificationOutcome outcome;
  outcome.run = true;
  outcome.maximumError = v.maxDistanceError;
  outcome.passed = v.ok(tolerance);
  if (!outcome.passed)
    outcome.report = v.problems(tolerance, mat, [&frame](const Vec3& x) { return frame.toUser(x); });
  return outcome;
}

void attachVerification(vtkDataObject* output, const VerificationOutcome& outcome)
{
  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkIntArray> status;
  status->SetName(arrays::VerificationStatus);
  status->InsertNextValue(outcome.run ? (outcome.passed ? 1 : 0) : -1);
  vtkNew<vtkDoubleArray> error;
  error->SetName(arrays::MaximumVerifiedError);
  error->InsertNextValue(outcome.maximumError);
  vtkNew<vtkStringArray> report;
  report->SetName(arrays::VerificationReport);
  report->InsertNextValue(outcome.report);
  fd->AddArray(status);
  fd->AddArray(error);
  fd->AddArray(report);
}

} // namespace exactmat
