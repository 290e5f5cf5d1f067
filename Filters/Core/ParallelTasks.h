// Coarse-grained parallelism over independent tasks, with the loops inside them serial.
#ifndef foldingmeshes_ParallelTasks_h
#define foldingmeshes_ParallelTasks_h

#include <vtkSMPTools.h>

#include <cstddef>

namespace foldingmeshes
{
namespace detail
{
/// True on a thread while it runs a task of RunTasksInParallel.
inline bool& InsideParallelTask()
{
  static thread_local bool inside = false;
  return inside;
}
}

/**
 * task(i) for every i in [0, n), in parallel through vtkSMPTools (one task at a time per
 * thread). Tasks must touch disjoint state; the results are then those of a serial loop,
 * for any thread count. Loops inside a task that go through ForRanges run serially: the
 * tasks are the parallelism there (VTK 9.2's STDThread backend would otherwise start a new
 * pool of threads for every nested loop).
 */
template <typename Task>
void RunTasksInParallel(std::size_t n, const Task& task)
{
  if (n == 1)
  {
    task(0);
    return;
  }
  vtkSMPTools::For(0,
    static_cast<vtkIdType>(n),
    1,
    [&](vtkIdType begin, vtkIdType end)
    {
      // Set for the tasks, restored however they end (a pooled thread runs other loops later).
      struct Inside
      {
        bool& flag;
        const bool outer;
        explicit Inside(bool& f)
          : flag(f)
          , outer(f)
        {
          flag = true;
        }
        ~Inside() { flag = outer; }
      } inside(detail::InsideParallelTask());
      for (vtkIdType i = begin; i < end; ++i)
        task(static_cast<std::size_t>(i));
    });
}

/// body(begin, end) over the ranges of [0, n): vtkSMPTools::For with `grain`, or one serial
/// call inside a task of RunTasksInParallel.
template <typename Body>
void ForRanges(vtkIdType n, vtkIdType grain, const Body& body)
{
  if (n <= 0)
    return;
  if (detail::InsideParallelTask())
    body(0, n);
  else
    vtkSMPTools::For(0, n, grain, body);
}
}

#endif
