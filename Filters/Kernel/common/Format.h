#pragma once
/// @file Format.h
/// @brief How error messages print points: "(x, y, z)" with 9 significant digits.

#include "common/Types.h"

#include <sstream>
#include <string>

namespace exactmat
{

/// A number with 9 significant digits ("1.5", not "1.5000000000000000").
inline std::string format(double v)
{
  std::ostringstream os;
  os.precision(9);
  os << v;
  return os.str();
}

inline std::string format(const Vec3& p)
{
  std::ostringstream os;
  os.precision(9);
  os << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return os.str();
}

} // namespace exactmat
