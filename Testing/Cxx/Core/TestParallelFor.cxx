// ParallelForRanges (the loops of the core on vtkSMPTools' threads, with a pool kept between
// loops under the STDThread backend) and RunTasksInParallel / ForRanges on top of it:
// - every index of [0, n) is covered exactly once, in ranges of at most `grain` (or one serial
//   range), for the
//   Sequential and STDThread backends and 1, 2 and 3 threads; with 2 threads and many ranges
//   both threads take part;
// - a loop started inside a range (nested) covers its indices once, in ranges of at most the
//   grain or one serial range; every task of RunTasksInParallel runs once; a thread that ran
//   out of tasks helps with the loops started inside the others' (loops inside a helped range
//   stay serial), and an exception thrown by a helped loop's range reaches the outer caller;
// - loops started at the same time from several threads all complete (one gets the pool, the
//   others run serially) and cover their indices once;
// - an exception thrown by a range reaches the caller, and the pool works afterwards;
// - a process forked after the pool started (its workers do not exist in the child) still
//   runs loops, in parallel, to the end;
// - the thread count follows vtkSMPTools::Initialize between loops.
#include "CoreTestUtilities.h"
#include "ParallelTasks.h"

#include <vtkSMPTools.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace
{
using foldingmeshes::ParallelForRanges;

/// Runs one loop; true when [0, n) was covered exactly once, in ranges of at most grain or in
/// one serial range.
/// `threadsSeen`: how many distinct threads ran ranges.
bool CoversOnce(vtkIdType n, vtkIdType grain, size_t* threadsSeen = nullptr)
{
  std::vector<std::atomic<int>> hits(static_cast<size_t>(n));
  std::atomic<bool> tooLong{ false };
  std::mutex lock;
  std::set<std::thread::id> threads;
  ParallelForRanges(n,
    grain,
    [&](vtkIdType begin, vtkIdType end)
    {
      if (grain > 0 && end - begin > grain && !(begin == 0 && end == n))
        tooLong = true;
      for (vtkIdType k = begin; k < end; ++k)
        ++hits[static_cast<size_t>(k)];
      // Enough work per range that a parked worker wakes up before the caller is done.
      volatile double x = 0.0;
      for (int i = 0; i < 20000; ++i)
        x = x + 1e-9 * i;
      std::lock_guard<std::mutex> guard(lock);
      threads.insert(std::this_thread::get_id());
    });
  if (threadsSeen)
    *threadsSeen = threads.size();
  bool once = !tooLong;
  for (const auto& h : hits)
    once = once && h == 1;
  return once;
}

/// `parallel`: the machine runs 2 threads at once (else only the coverage is checked).
void CheckCoverage(bool parallel)
{
  for (const char* backend : { "Sequential", "STDThread" })
    for (int threads : { 1, 2, 3 })
    {
      vtkSMPTools::SetBackend(backend);
      vtkSMPTools::Initialize(threads);
      for (vtkIdType n : { 1, 2, 7, 64, 1000, 4099 })
        for (vtkIdType grain : { 0, 1, 16, 5000 })
          EXPECT(CoversOnce(n, grain),
            backend << ", " << threads << " threads: n " << n << " grain " << grain
                    << " not covered exactly once in ranges of at most the grain");
    }
  if (!parallel)
    return;
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  size_t seen = 0;
  bool both = false;
  for (int attempt = 0; attempt < 200 && !both; ++attempt) // a busy machine may park the worker
  {
    EXPECT(CoversOnce(400, 1, &seen), "400 ranges, 2 threads: not covered once");
    both = seen == 2;
  }
  EXPECT(both, "2 threads, 400 ranges: only " << seen << " thread(s) ran ranges");
  vtkSMPTools::Initialize(1);
  EXPECT(CoversOnce(400, 1, &seen) && seen == 1,
    "after Initialize(1): " << seen << " threads ran ranges");
}

void CheckNesting()
{
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  // Inner loops cover their indices once, in ranges of at most the grain or one whole range
  // (serial); whichever thread runs an inner range knows it is inside a loop.
  std::atomic<int> flagged{ 0 }, outerRanges{ 0 }, innerBad{ 0 }, innerUnflagged{ 0 };
  ParallelForRanges(64,
    4,
    [&](vtkIdType, vtkIdType)
    {
      ++outerRanges;
      flagged += foldingmeshes::InsideParallelLoop();
      std::vector<std::atomic<int>> hits(1000);
      ParallelForRanges(1000,
        16,
        [&](vtkIdType begin, vtkIdType end)
        {
          if (end - begin > 16 && !(begin == 0 && end == 1000))
            ++innerBad;
          innerUnflagged += !foldingmeshes::InsideParallelLoop();
          for (vtkIdType k = begin; k < end; ++k)
            ++hits[static_cast<size_t>(k)];
        });
      for (const auto& h : hits)
        innerBad += h != 1;
    });
  EXPECT(flagged == 16, flagged << " of 16 ranges know they run inside a loop");
  EXPECT(outerRanges == 16 && innerBad == 0 && innerUnflagged == 0,
    "nested loops: " << innerBad << " indices not covered once or ranges over the grain, "
                     << innerUnflagged << " inner ranges not flagged");
  EXPECT(!foldingmeshes::InsideParallelLoop(), "the flag stays set after a loop");

  std::vector<std::atomic<int>> runs(37);
  std::atomic<int> taskInnerBad{ 0 };
  foldingmeshes::RunTasksInParallel(runs.size(),
    [&](size_t i)
    {
      ++runs[i];
      std::vector<std::atomic<int>> hits(1000);
      foldingmeshes::ForRanges(1000,
        16,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType k = begin; k < end; ++k)
            ++hits[static_cast<size_t>(k)];
        });
      for (const auto& h : hits)
        taskInnerBad += h != 1;
    });
  bool once = true;
  for (const auto& r : runs)
    once = once && r == 1;
  EXPECT(once, "every task runs exactly once");
  EXPECT(taskInnerBad == 0, "loops inside tasks: " << taskInnerBad << " indices not covered once");
}

/// A thread that has run out of tasks helps with the loops the others start inside theirs:
/// task 1 starts inner loops (after task 0 is done) until one of its ranges runs on another
/// thread. Loops inside a helped range run serially; an exception thrown by an inner range on
/// either thread reaches the outer caller, and the pool works afterwards.
void CheckIdleThreadsHelp()
{
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  std::atomic<bool> firstDone{ false }, helped{ false };
  std::atomic<int> badCoverage{ 0 }, deepNotWhole{ 0 }, loops{ 0 };
  foldingmeshes::RunTasksInParallel(2,
    [&](size_t i)
    {
      if (i == 0)
      {
        firstDone = true;
        return;
      }
      while (!firstDone)
        std::this_thread::yield();
      const std::thread::id self = std::this_thread::get_id();
      for (int attempt = 0; attempt < 2000 && !helped; ++attempt)
      {
        ++loops;
        std::vector<std::atomic<int>> hits(64);
        foldingmeshes::ForRanges(64,
          1,
          [&](vtkIdType begin, vtkIdType end)
          {
            for (vtkIdType k = begin; k < end; ++k)
              ++hits[static_cast<size_t>(k)];
            if (std::this_thread::get_id() != self)
              helped = true;
            foldingmeshes::ForRanges(
              100, 1, [&](vtkIdType b, vtkIdType e) { deepNotWhole += !(b == 0 && e == 100); });
            volatile double x = 0.0;
            for (int j = 0; j < 2000; ++j)
              x = x + 1e-9 * j;
          });
        for (const auto& h : hits)
          badCoverage += h != 1;
        if (!helped)
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    });
  EXPECT(helped, "in " << loops << " inner loops the idle thread never helped");
  EXPECT(badCoverage == 0 && deepNotWhole == 0,
    "helped loops: " << badCoverage << " indices not covered once, " << deepNotWhole
                     << " loops inside a helped range not serial");

  for (const bool onStarter : { true, false })
  {
    bool caught = false, thrown = false;
    try
    {
      std::atomic<bool> done{ false };
      foldingmeshes::RunTasksInParallel(2,
        [&](size_t i)
        {
          if (i == 0)
          {
            done = true;
            return;
          }
          while (!done)
            std::this_thread::yield();
          const std::thread::id self = std::this_thread::get_id();
          std::atomic<bool> once{ false };
          for (int attempt = 0; attempt < 2000; ++attempt)
          {
            foldingmeshes::ForRanges(64,
              1,
              [&](vtkIdType, vtkIdType)
              {
                volatile double x = 0.0;
                for (int j = 0; j < 2000; ++j)
                  x = x + 1e-9 * j;
                if ((std::this_thread::get_id() == self) == onStarter && !once.exchange(true))
                  throw std::runtime_error("from an inner range");
              });
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          }
        });
    }
    catch (const std::runtime_error& e)
    {
      thrown = true;
      caught = std::string(e.what()) == "from an inner range";
    }
    EXPECT(thrown && caught,
      "an exception thrown by an inner range on the "
        << (onStarter ? "thread that started it" : "helping thread")
        << " does not reach the outer caller");
    EXPECT(CoversOnce(1000, 10), "the pool does not work after an inner exception");
  }
}

void CheckConcurrentCallers()
{
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  std::atomic<int> good{ 0 };
  std::vector<std::thread> callers;
  for (int c = 0; c < 4; ++c)
    callers.emplace_back(
      [&]()
      {
        for (int k = 0; k < 25; ++k)
          good += CoversOnce(300, 8);
      });
  for (auto& t : callers)
    t.join();
  EXPECT(good == 100, "concurrent loops from 4 threads: " << good << " of 100 covered once");
}

void CheckException()
{
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  const std::thread::id caller = std::this_thread::get_id();
  // Thrown on the calling thread, then on a worker (the first range run there).
  for (const bool onCaller : { true, false })
  {
    // A busy machine may leave every range to the other thread: try again until the
    // thread asked for ran one (each try must pass the exception on).
    std::atomic<bool> thrown{ false };
    for (int attempt = 0; attempt < 50 && !thrown; ++attempt)
    {
      bool caught = false;
      try
      {
        ParallelForRanges(1000,
          1,
          [&](vtkIdType, vtkIdType)
          {
            volatile double x = 0.0;
            for (int i = 0; i < 2000; ++i)
              x = x + 1e-9 * i;
            if ((std::this_thread::get_id() == caller) == onCaller && !thrown.exchange(true))
              throw std::runtime_error("from a range");
          });
      }
      catch (const std::runtime_error& e)
      {
        caught = std::string(e.what()) == "from a range";
      }
      EXPECT(caught == thrown.load(),
        "an exception thrown by a range on the " << (onCaller ? "calling thread" : "worker")
                                                 << " does not reach the caller");
    }
    EXPECT(onCaller ? thrown.load() : true, "the calling thread ran no range in 50 loops");
    EXPECT(CoversOnce(1000, 10), "the pool does not work after an exception");
  }
}

void CheckFork()
{
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  EXPECT(CoversOnce(200, 1), "before the fork: not covered once"); // the pool exists now
  const pid_t child = fork();
  if (child == 0)
  {
    alarm(60); // a hang fails instead of waiting for the test's timeout
    size_t seen = 0;
    bool ok = CoversOnce(400, 1, &seen);
    for (int attempt = 0; attempt < 200 && ok && seen < 2; ++attempt)
      ok = CoversOnce(400, 1, &seen);
    _exit(ok && seen == 2 ? 0 : 1);
  }
  int status = -1;
  EXPECT(child > 0 && waitpid(child, &status, 0) == child, "fork/waitpid failed");
  EXPECT(WIFEXITED(status) && WEXITSTATUS(status) == 0,
    "a forked child could not run a parallel loop (status " << status << ")");
}
}

int main()
{
  alarm(300); // a deadlock fails instead of waiting for ctest's timeout
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  if (vtkSMPTools::GetEstimatedNumberOfThreads() < 2)
  {
    // VTK caps the thread count at the hardware's: nothing runs in parallel here.
    std::printf("TestParallelFor: one hardware thread, parallel checks skipped\n");
    CheckCoverage(false);
    return coretest::Finish("TestParallelFor");
  }
  CheckCoverage(true);
  CheckNesting();
  CheckIdleThreadsHelp();
  CheckConcurrentCallers();
  CheckException();
#if !defined(__SANITIZE_THREAD__)
  CheckFork(); // ThreadSanitizer ends forked children of threaded processes (exit 66)
#endif
  vtkSMPTools::SetBackend("Sequential");
  return coretest::Finish("TestParallelFor");
}
