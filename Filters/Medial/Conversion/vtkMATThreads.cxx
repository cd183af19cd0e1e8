#include "vtkMATThreads.h"

#include <vtkSMPTools.h>

#include <string>

namespace exactmat
{

ParallelFor smpParallelFor()
{
  return [](std::size_t n, const std::function<void(std::size_t, std::size_t)>& body) {
    if (n == 0)
      return;
    vtkSMPTools::For(vtkIdType(0), static_cast<vtkIdType>(n),
      [&body](vtkIdType begin, vtkIdType end) {
        body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
      });
  };
}

void withThreads(int threads, const std::function<void()>& work)
{
  if (vtkSMPTools::IsParallelScope())
  {
    work(); // already inside a parallel loop (a part of a collection): stay on this thread
    return;
  }
  const std::string backend = threads == 1 ? "Sequential" : "STDThread";
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads > 0 ? threads : 0, backend, false },
    [&work]() { work(); });
}

int threadsFor(int threads)
{
  int n = 1;
  withThreads(threads, [&n]() { n = vtkSMPTools::GetEstimatedNumberOfThreads(); });
  return n;
}

} // namespace exactmat
