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

} // namespace exactmat
