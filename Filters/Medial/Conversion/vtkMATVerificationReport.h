#ifndef vtkMATVerificationReport_h
#define vtkMATVerificationReport_h
/**
 * @file vtkMATVerificationReport.h
 * @brief How a MAT filter publishes its own verification: field data on the output
 * (`VerificationStatus`, `MaximumVerifiedError`, `VerificationReport`; see
 * vtkExactMATArrayNames.h), so a pipeline, a script or the CLI can see a failed check
 * without calling the filter's getters. The filter itself warns (vtkWarningMacro).
 */

#include <vtkDataObject.h>

#include <string>

namespace exactmat
{

struct VerificationOutcome
{
  bool run = false;    ///< VerifyOutput was on
  bool passed = true;  ///< every check within its tolerance
  double maximumError = 0.0;
  std::string report;  ///< what failed and where ("" when passed)
};

/// Adds the outcome's field data arrays to `output`.
void attachVerification(vtkDataObject* output, const VerificationOutcome& outcome);

} // namespace exactmat

#endif
