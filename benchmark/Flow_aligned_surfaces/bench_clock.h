// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The clocks the benchmarks share: the CPU time of the calling thread, which unlike the wall
// clock does not count the time it waited for a core (on a shared machine it tells noise from
// cost), the process's minor page faults (first touches of fresh memory), and what one first
// touch costs on this machine (about 10 us on the benchmarks' virtual machine, so that a few
// thousand faults are milliseconds of a construction).

#ifndef FAS_BENCHMARK_BENCH_CLOCK_H
#define FAS_BENCHMARK_BENCH_CLOCK_H

#include <sys/mman.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

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

/// Microseconds per first touch of a page of fresh anonymous memory (median of 5 rounds of
/// 32 MiB, each a new mapping written once per page).
inline double first_touch_us()
{
  const std::size_t bytes = std::size_t(32) << 20, page = 4096;
  std::vector<double> rounds;
  for (int r = 0; r < 5; ++r) {
    void* memory = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (memory == MAP_FAILED)
      return std::nan("");
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t offset = 0; offset < bytes; offset += page)
      static_cast<volatile char*>(memory)[offset] = 1;
    const auto end = std::chrono::steady_clock::now();
    munmap(memory, bytes);
    rounds.push_back(std::chrono::duration<double, std::micro>(end - start).count() / double(bytes / page));
  }
  std::sort(rounds.begin(), rounds.end());
  return rounds[rounds.size() / 2];
}

} // namespace fas_benchmark

#endif // FAS_BENCHMARK_BENCH_CLOCK_H
