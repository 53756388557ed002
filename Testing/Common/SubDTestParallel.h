// Test support: a ParallelFor that cuts loops finely and runs them on three threads, so that
// kernel passes can be checked to give the serial result however a loop is split.
#ifndef SubDTestParallel_h
#define SubDTestParallel_h

#include "SubDParallel.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace subdtest
{
/// Three threads, each taking ranges of two items in turn.
inline void ThreeThreadFor(subd::Index begin, subd::Index end, const subd::RangeTask& task)
{
  std::vector<std::thread> threads;
  for (subd::Index t = 0; t < 3; ++t)
  {
    threads.emplace_back([=, &task]() {
      for (subd::Index b = begin + 2 * t; b < end; b += 6)
      {
        task(b, std::min(end, b + 2));
      }
    });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
}
}

#endif
