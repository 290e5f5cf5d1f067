// Coarse-grained parallelism over independent tasks, and parallel loops over index ranges,
// with the loops inside them serial unless a thread has run out of tasks (ParallelFor.h).
#ifndef foldingmeshes_ParallelTasks_h
#define foldingmeshes_ParallelTasks_h

#include "ParallelFor.h"

#include <cstddef>

namespace foldingmeshes
{
/**
 * task(i) for every i in [0, n), in parallel (ParallelForRanges, one task at a time per
 * thread). Tasks must touch disjoint state; the results are then those of a serial loop,
 * for any thread count. Loops inside tasks that run in parallel (ForRanges,
 * ParallelForRanges) run serially while every thread has a task: the tasks are the
 * parallelism there; a thread that has run out of tasks helps with them (ParallelFor.h), and
 * a single task, or tasks run one after the other, use parallel loops.
 */
template <typename Task>
void RunTasksInParallel(std::size_t n, const Task& task)
{
  if (n == 1)
  {
    task(0);
    return;
  }
  ParallelForRanges(static_cast<vtkIdType>(n),
    1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
        task(static_cast<std::size_t>(i));
    });
}

/// body(begin, end) over ranges of at most `grain` indices covering [0, n): ParallelForRanges
/// (inside a task or another loop: one serial call, or ranges shared with idle threads).
template <typename Body>
void ForRanges(vtkIdType n, vtkIdType grain, const Body& body)
{
  ParallelForRanges(n, grain, body);
}
}

#endif
