#pragma once
/// @file ParallelFor.h
/// @brief How the kernel runs independent work on several threads without depending on
/// a threading library: a caller-supplied loop runner. The VTK layer passes one built on
/// vtkSMPTools (Conversion/vtkMATThreads.h); the default runs the loop here, in order.
///
/// The kernel only hands out work whose items are independent and whose results are
/// stored per item and reduced in item order afterwards, so a threaded run gives the same
/// figures as a sequential one, bit for bit.

#include <cstddef>
#include <functional>

namespace exactmat
{

/// Calls body(begin, end) on disjoint ranges covering [0, n), possibly concurrently.
using ParallelFor =
  std::function<void(std::size_t n, const std::function<void(std::size_t, std::size_t)>& body)>;

/// The sequential runner: body(0, n) on this thread.
inline void sequentialFor(
  std::size_t n, const std::function<void(std::size_t, std::size_t)>& body)
{
  if (n > 0)
    body(0, n);
}

} // namespace exactmat
