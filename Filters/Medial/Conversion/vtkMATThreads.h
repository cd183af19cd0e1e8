#ifndef vtkMATThreads_h
#define vtkMATThreads_h
/**
 * @file vtkMATThreads.h
 * @brief The MAT filters' threads, on vtkSMPTools: the kernel's ParallelFor runner, and
 * the scope that selects the STDThread backend and a thread count.
 *
 * Why a scope: Debian's VTK is built with the Sequential backend as its default, so
 * vtkSMPTools loops run on one thread unless a backend is chosen. A filter runs its work
 * inside withThreads(NumberOfThreads, …); vtkSMPTools::LocalScope restores the user's
 * global choice afterwards. Nested loops (a part's verification inside the loop over a
 * collection's parts) run sequentially in their thread: VTK's default, no oversubscription.
 */

#include "common/ParallelFor.h"

#include <functional>

namespace exactmat
{

/// A ParallelFor over vtkSMPTools::For in the current scope's backend and thread count.
ParallelFor smpParallelFor();

/// Runs `work` with vtkSMPTools on the STDThread backend with `threads` threads
/// (0: every core, or VTK_SMP_MAX_THREADS when set; 1: the Sequential backend).
void withThreads(int threads, const std::function<void()>& work);

/// The number of threads withThreads(threads, …) runs on.
int threadsFor(int threads);

} // namespace exactmat

#endif
