#pragma once
/// @file Format.h
/// @brief How error messages print points: "(x, y, z)" with 9 significant digits.

#include "common/Types.h"

#include <sstream>
#include <string>

namespace exactmat
{

inline std::string format(const Vec3& p)
{
  std::ostringstream os;
  os.precision(9);
  os << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return os.str();
}

} // namespace exactmat
