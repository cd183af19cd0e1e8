#ifndef vtkMATVerificationReport_h
#define vtkMATVerificationReport_h
/**
 * @file vtkMATVerificationReport.h
 * @brief How a MAT filter publishes its own verification: field data on the output
 * (`VerificationStatus`, `MaximumVerifiedError`, `VerificationReport`; see
 * vtkExactMATArrayNames.h), so a pipeline, a script or the CLI can see a failed check
 * without calling the filter's getters. The filter itself warns (vtkWarningMacro).
 */

#include "common/Normalisation.h"
#include "medial/Verification.h"

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

/// The outcome of checking a solid's MAT (2.5D or 3D) against `tolerance`, the report's
/// places in the user's frame.
VerificationOutcome outcomeOf(const MedialVerification& v, double tolerance, const MedialComplex& mat,
  const Normalisation& frame);

/// Adds the outcome's field data arrays to `output`.
void attachVerification(vtkDataObject* output, const VerificationOutcome& outcome);

} // namespace exactmat

#endif
