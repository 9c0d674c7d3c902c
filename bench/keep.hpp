// bench/keep.hpp -- keep(v): stop the optimiser from removing the timed computation of v.
// Google Benchmark 1.7's DoNotOptimize(T&) binds v through an asm "+m,r" constraint; with GCC -O3
// a double bound that way can come back as garbage after the loop (measured: the fast bound path
// read 1e-310 instead of 0.01, so its accuracy counter said rel_err = 1). keep() hands the
// optimiser v's address and a memory clobber instead, so v stays in memory and intact.
#pragma once

#include <benchmark/benchmark.h>

template <class T>
inline void keep(T& v) {
  T* p = &v;
  benchmark::DoNotOptimize(p);
  benchmark::ClobberMemory();
}
