#pragma once
// Counts heap allocations of the whole program (operator new is replaced in
// allocation_counter.cpp), so tests and benchmarks can prove that per-frame code allocates nothing.

namespace thespis::test {
long allocationCount();
} // namespace thespis::test
