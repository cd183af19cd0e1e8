#ifndef vtkMATPartResult_h
#define vtkMATPartResult_h
/**
 * @file vtkMATPartResult.h
 * @brief What a MAT filter learns about one boundary (one part): named figures (counts and
 * timings), and the outcome of its self-verification. vtkMATAlgorithm publishes them as
 * the filter's getters, as field data on the part's output, and, for a collection of
 * parts, as one row per part in the output's summary arrays.
 */

#include "vtkMATVerificationReport.h"

#include <string>
#include <vector>

namespace exactmat
{

struct PartFigure
{
  std::string name; ///< as the filter's getter is named: "NumberOfSegments", "TracingSeconds"
  double value = 0.0;
  bool integer = true; ///< a count (an int array) or a measure (a double array)
};

struct PartResult
{
  std::vector<PartFigure> figures;
  VerificationOutcome verification;

  void count(const std::string& name, int value) { figures.push_back({ name, double(value), true }); }
  void measure(const std::string& name, double value) { figures.push_back({ name, value, false }); }
  /// The figure's value, 0 when the part has no such figure.
  double get(const std::string& name) const
  {
    for (const PartFigure& f : figures)
      if (f.name == name)
        return f.value;
    return 0.0;
  }
};

} // namespace exactmat

#endif
