#ifndef vtkMATReaderErrors_h
#define vtkMATReaderErrors_h
/**
 * @file vtkMATReaderErrors.h
 * @brief What ExactMAT's readers do with the exceptions of reading and converting a file:
 * one message each, naming the file, for the reader's vtkErrorMacro. Not wrapped.
 */

#include "common/InputError.h"

#include <exception>
#include <new>
#include <string>

namespace exactmat
{
/// Runs `work` (read `fileName` and convert it); an exception becomes one message passed to
/// `report` (InputError's own text, which names the file and entity; out of memory; other
/// internal errors), and the result is false. True when `work` returned normally.
template <typename Work, typename Report>
bool readReportingErrors(const char* fileName, Work&& work, Report&& report)
{
  try
  {
    work();
    return true;
  }
  catch (const InputError& e)
  {
    report(std::string(e.what()));
  }
  catch (const std::bad_alloc&)
  {
    report("out of memory reading " + std::string(fileName));
  }
  catch (const std::exception& e)
  {
    report("internal error reading " + std::string(fileName) + ": " + e.what());
  }
  return false;
}
} // namespace exactmat

#endif
