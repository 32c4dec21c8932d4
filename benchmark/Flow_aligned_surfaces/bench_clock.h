// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The clocks the benchmarks share: the CPU time of the calling thread, which unlike the wall
// clock does not count the time it waited for a core (on a shared machine it tells noise from
// cost), and the process's minor page faults (first touches of fresh memory, about 10 us each
// on the benchmarks' virtual machine).

#ifndef FAS_BENCHMARK_BENCH_CLOCK_H
#define FAS_BENCHMARK_BENCH_CLOCK_H

#include <sys/resource.h>
#include <time.h>

namespace fas_benchmark {

/// CPU time of the calling thread, in milliseconds.
inline double thread_cpu_ms()
{
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

/// Minor page faults of the process so far.
inline long minor_faults()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

} // namespace fas_benchmark

#endif // FAS_BENCHMARK_BENCH_CLOCK_H
