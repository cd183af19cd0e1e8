#pragma once
/// @file InputError.h
/// @brief The one exception the kernel throws for bad input.
///
/// Every check on user data throws `exactmat::InputError` with a message that names the
/// entity (curve, loop, face, control point) and the problem. The VTK layer turns it into
/// `vtkErrorMacro` + a failed `RequestData`; nothing in the kernel prints or aborts.

#include <sstream>
#include <stdexcept>
#include <string>

namespace exactmat
{

class InputError : public std::runtime_error
{
public:
  explicit InputError(const std::string& what)
    : std::runtime_error(what)
  {
  }
};

/// Builds an InputError message from stream-able parts: `fail("curve ", i, ": weight ", w)`.
template <typename... Parts>
[[noreturn]] void fail(const Parts&... parts)
{
  std::ostringstream os;
  os.precision(17);
  (os << ... << parts);
  throw InputError(os.str());
}

/// A user-set parameter must be a number in [lo, hi]: NaN slips through clamping setters
/// (every comparison with NaN is false), so each run checks its parameters by name.
inline void checkParameter(const char* name, double value, double lo, double hi)
{
  if (!(value >= lo && value <= hi))
  {
    fail(name, " is ", value, "; it must be a number from ", lo, " to ", hi);
  }
}

} // namespace exactmat
