// A parallel loop over index ranges on vtkSMPTools' threads, without VTK 9.2's cost per loop.
#ifndef foldingmeshes_ParallelFor_h
#define foldingmeshes_ParallelFor_h

#include <vtkType.h>

#include <functional>

namespace foldingmeshes
{
/// body(begin, end) over consecutive ranges covering [0, n) once.
using RangeBody = std::function<void(vtkIdType, vtkIdType)>;

/**
 * Calls body(begin, end) for ranges that together cover [0, n) exactly once: in parallel,
 * ranges of at most `grain` indices (grain <= 0: about a quarter of an equal share per
 * thread); serially (one thread, the Sequential backend, grain >= n, nested), one range.
 *
 * The thread count and the backend are vtkSMPTools' (vtkSMPTools::Initialize,
 * VTK_SMP_MAX_THREADS, VTK_SMP_BACKEND_IN_USE). With the STDThread backend the ranges run on a
 * pool of threads kept between loops, the calling thread taking part: VTK 9.2's STDThread
 * backend starts and joins a new pool for every vtkSMPTools::For (about 0.13 ms with two
 * threads, measured; hundreds of loops per folding tree). Other parallel backends (TBB,
 * OpenMP) keep their own threads: the loop is a vtkSMPTools::For there; Sequential runs one
 * range.
 *
 * A loop started inside a range of the pool's loop (nested) goes to the pool's threads that
 * have run out of ranges, if any is waiting (ranges of `grain`, the starting thread taking
 * part; one such loop at a time): uneven tasks do not leave a core idle. Otherwise - no idle
 * thread, inside a range of such a nested loop, inside another backend's loop, while another
 * thread's loop occupies the pool, or when no worker thread can be started - the loop runs
 * serially on the calling thread as one range. Which thread runs a range, and how a loop is
 * cut into ranges, are not fixed: bodies must write disjoint results per index (no
 * per-thread or per-range state that reaches the results) for results that do not depend
 * on the thread count. An exception thrown
 * by a range reaches the caller (the first one; the other threads stop after their current
 * range). A process forked outside a loop gets a pool of its own; one forked inside a range
 * must exec (or exit) without returning from it.
 */
void ParallelForRanges(vtkIdType n, vtkIdType grain, const RangeBody& body);

/// True on a thread while it runs a range of a parallel ParallelForRanges (so also a task of a
/// parallel RunTasksInParallel); not in the serial cases above.
bool InsideParallelLoop();
}

#endif
