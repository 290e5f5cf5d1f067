#include "ParallelFor.h"

#include <vtkSMPTools.h>

#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace foldingmeshes
{
namespace
{
/// The thread runs ranges of a parallel loop (InsideParallelLoop; nested loops see it).
thread_local bool insideLoop = false;
/// The thread runs a range of the pool's loop (not of a loop posted from inside one).
thread_local bool inPoolRange = false;

/// Sets a thread-local flag for a scope; restores the previous value however it ends.
struct FlagScope
{
  bool& flag;
  const bool outer = flag;
  explicit FlagScope(bool& f)
    : flag(f)
  {
    flag = true;
  }
  ~FlagScope() { flag = outer; }
  FlagScope(const FlagScope&) = delete;
  FlagScope& operator=(const FlagScope&) = delete;
};

/**
 * Worker threads parked between loops. One loop at a time: the calling thread claims ranges
 * too, the workers asked to take part claim the rest while the loop is open, and the caller,
 * once every range is claimed, closes the loop and returns when the workers that joined are
 * done. A thread that finds no range left while others still run theirs is idle: a loop
 * started inside a range (RunNested) is posted to the idle threads, which claim its ranges
 * beside the thread that started it (one posted loop at a time; loops inside its ranges run
 * serially), so uneven tasks (IRLS runs of 11 and 66 iterations) do not leave a core waiting.
 * The pool is never destroyed (its parked threads end with the process), so
 * no static destructor has to join threads during exit or a plugin's unloading.
 */
class ThreadPool
{
public:
  /// False, without running anything, when another thread's loop occupies the pool or no
  /// worker thread could be started.
  bool Run(int threads, vtkIdType n, vtkIdType grain, const RangeBody& body)
  {
    std::unique_lock<std::mutex> busy(this->Busy, std::try_to_lock);
    if (!busy.owns_lock())
      return false;
    const vtkIdType ranges = (n + grain - 1) / grain;
    int helpers = static_cast<int>(std::min<vtkIdType>(threads - 1, ranges - 1));
    {
      std::lock_guard<std::mutex> lock(this->Lock);
      try
      {
        while (static_cast<int>(this->Workers.size()) < helpers)
        {
          const int index = static_cast<int>(this->Workers.size());
          this->Workers.emplace_back([this, index]() { this->Work(index); });
        }
      }
      catch (const std::system_error&)
      {
        // No more threads (a process or system limit): the ones there are.
        helpers = static_cast<int>(this->Workers.size());
      }
      if (helpers < 1)
        return false;
      this->Body = &body;
      this->N = n;
      this->Grain = grain;
      this->Next = 0;
      this->Error = nullptr;
      this->Helpers = helpers;
      this->Open = true;
      this->Active = 0;
      this->Threads = helpers + 1;
      this->Participants = 1;
      ++this->Generation;
    }
    this->Wake.notify_all();
    this->RunRanges();
    // Every range is claimed now: workers that have not joined yet need not (under load they
    // may wake much later); wait only for those that did.
    std::unique_lock<std::mutex> lock(this->Lock);
    this->HelpUntilRangesEnd(lock);
    this->Open = false;
    this->Finished.wait(lock, [this]() { return this->Active == 0; });
    this->Body = nullptr;
    std::exception_ptr error = this->Error;
    this->Error = nullptr;
    lock.unlock();
    if (error)
      std::rethrow_exception(error);
    return true;
  }

private:
  void Work(int index)
  {
    unsigned long long seen = 0;
    std::unique_lock<std::mutex> lock(this->Lock);
    for (;;)
    {
      this->Wake.wait(lock, [&]() { return this->Generation != seen; });
      seen = this->Generation;
      if (index >= this->Helpers || !this->Open)
        continue;
      ++this->Active;
      ++this->Participants;
      lock.unlock();
      this->RunRanges();
      lock.lock();
      this->HelpUntilRangesEnd(lock);
      if (--this->Active == 0 && !this->Open)
        this->Finished.notify_one();
    }
  }

public:
  /**
   * Called inside a range of the current loop (by the thread running it): runs
   * body(begin, end) over [0, n) with the idle threads of the loop, the caller taking part,
   * and returns true when every range is done; false, without running anything, when no
   * thread is idle or another posted loop is under way.
   */
  bool RunNested(vtkIdType n, vtkIdType grain, const RangeBody& body)
  {
    if (this->Idle.load(std::memory_order_relaxed) == 0) // the common case: no lock taken
      return false;
    {
      std::lock_guard<std::mutex> lock(this->Lock);
      if (this->Idle == 0 || this->NestedBody)
        return false;
      if (grain <= 0)
        grain = std::max<vtkIdType>(1, n / (4 * std::max(1, this->Threads)));
      if (grain >= n)
        return false;
      this->NestedBody = &body;
      this->NestedN = n;
      this->NestedGrain = grain;
      this->NestedNext = 0;
      this->NestedError = nullptr;
    }
    this->Help.notify_all();
    this->RunNestedRanges();
    std::unique_lock<std::mutex> lock(this->Lock);
    this->NestedDone.wait(lock, [this]() { return this->NestedActive == 0; });
    this->NestedBody = nullptr;
    std::exception_ptr error = this->NestedError;
    this->NestedError = nullptr;
    lock.unlock();
    if (error)
      std::rethrow_exception(error);
    return true;
  }

private:
  /// After a thread's last range (Lock held): while other threads still run ranges, helps
  /// with the loops they post (RunNested); returns when no thread runs a range.
  void HelpUntilRangesEnd(std::unique_lock<std::mutex>& lock)
  {
    if (--this->Participants == 0)
    {
      this->Help.notify_all();
      return;
    }
    ++this->Idle;
    for (;;)
    {
      this->Help.wait(lock,
        [this]()
        {
          return this->Participants == 0 ||
            (this->NestedBody && this->NestedNext.load() < this->NestedN);
        });
      if (this->Participants == 0)
        break;
      --this->Idle;
      ++this->NestedActive;
      lock.unlock();
      this->RunNestedRanges();
      lock.lock();
      ++this->Idle;
      if (--this->NestedActive == 0)
        this->NestedDone.notify_all();
    }
    --this->Idle;
  }

  /// Claims and runs ranges of the posted loop until none is left.
  void RunNestedRanges()
  {
    FlagScope inside(insideLoop); // the thread runs ranges
    this->ClaimRanges(
      *this->NestedBody, this->NestedN, this->NestedGrain, this->NestedNext, this->NestedError);
  }

  /// Claims and runs ranges until none is left.
  void RunRanges()
  {
    FlagScope inside(insideLoop); // the thread runs ranges
    FlagScope poolRange(inPoolRange);
    this->ClaimRanges(*this->Body, this->N, this->Grain, this->Next, this->Error);
  }

  /// body's ranges of `grain` from `next` on, until none is left below n; the first exception
  /// goes to `error` and makes the other threads stop after their current range.
  void ClaimRanges(const RangeBody& body,
    vtkIdType n,
    vtkIdType grain,
    std::atomic<vtkIdType>& next,
    std::exception_ptr& error)
  {
    for (;;)
    {
      const vtkIdType begin = next.fetch_add(grain);
      if (begin >= n)
        return;
      try
      {
        body(begin, std::min(n, begin + grain));
      }
      catch (...)
      {
        std::lock_guard<std::mutex> lock(this->ErrorLock);
        if (!error)
          error = std::current_exception();
        next = n;
      }
    }
  }

  std::mutex Busy; ///< held by the thread whose loop uses the pool
  std::mutex Lock; ///< guards the loop's fields and the counters below
  std::condition_variable Wake, Finished;
  std::vector<std::thread> Workers;
  unsigned long long Generation = 0; ///< one more per loop
  int Helpers = 0;                   ///< workers that may take part in the current loop
  bool Open = false;                 ///< workers may still join the current loop
  int Active = 0;                    ///< workers that joined it and have not finished
  const RangeBody* Body = nullptr;
  vtkIdType N = 0, Grain = 1;
  std::atomic<vtkIdType> Next{ 0 }; ///< first index of the next unclaimed range
  std::mutex ErrorLock;
  std::exception_ptr Error; ///< the first exception thrown by a range
  int Threads = 1;          ///< threads that may take part in the current loop
  int Participants = 0;     ///< threads running (or about to claim) its ranges
  /// Threads waiting in HelpUntilRangesEnd, not helping (changed under Lock; read without
  /// it only to skip taking Lock when it is 0).
  std::atomic<int> Idle{ 0 };
  std::condition_variable Help, NestedDone;
  const RangeBody* NestedBody = nullptr; ///< the posted loop (null: none)
  vtkIdType NestedN = 0, NestedGrain = 1;
  std::atomic<vtkIdType> NestedNext{ 0 };
  int NestedActive = 0; ///< idle threads that joined the posted loop and have not finished
  std::exception_ptr NestedError;
};

std::mutex poolCreation;
ThreadPool* pool = nullptr;

/// The pool, created on first use. A process forked from one with a pool starts a new one:
/// the parent's workers do not exist in the child (the old pool is abandoned, never touched).
ThreadPool& Pool()
{
  static const bool registered = []()
  {
    pthread_atfork([]() { poolCreation.lock(); },
      []() { poolCreation.unlock(); },
      []()
      {
        pool = nullptr;
        poolCreation.unlock();
      });
    return true;
  }();
  (void)registered;
  std::lock_guard<std::mutex> lock(poolCreation);
  if (!pool)
    pool = new ThreadPool();
  return *pool;
}
}

bool InsideParallelLoop()
{
  return insideLoop;
}

void ParallelForRanges(vtkIdType n, vtkIdType grain, const RangeBody& body)
{
  if (n <= 0)
    return;
  // Serial without asking VTK for the thread count: GetEstimatedNumberOfThreads reads
  // /sys on every call (std::thread::hardware_concurrency), which cost a quarter of a
  // compress run when FaceTree::Build asked it at each of its small inner nodes.
  if (insideLoop || (grain > 0 && grain >= n))
  {
    // Inside a range of the pool's loop, a loop may go to threads that have run out of
    // ranges; elsewhere (inside a posted loop, a vtkSMPTools backend's loop) it is serial.
    if (!(inPoolRange && grain < n && pool && pool->RunNested(n, grain, body)))
      body(0, n);
    return;
  }
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  if (grain <= 0)
    grain = std::max<vtkIdType>(1, n / (4 * std::max(1, threads)));
  if (insideLoop || threads <= 1 || grain >= n)
  {
    body(0, n);
    return;
  }
  const char* backend = vtkSMPTools::GetBackend();
  if (backend && std::strcmp(backend, "STDThread") == 0)
  {
    if (!Pool().Run(threads, n, grain, body))
      body(0, n);
    return;
  }
  if (backend && std::strcmp(backend, "Sequential") == 0)
  {
    body(0, n);
    return;
  }
  vtkSMPTools::For(0,
    n,
    grain,
    [&](vtkIdType begin, vtkIdType end)
    {
      FlagScope inside(insideLoop); // the thread runs ranges
      body(begin, end);
    });
}
}
