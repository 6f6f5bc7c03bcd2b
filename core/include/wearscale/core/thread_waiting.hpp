#pragma once
// How idle OpenMP threads wait between parallel regions. libgomp reads
// OMP_WAIT_POLICY and GOMP_SPINCOUNT once, when it is loaded, before main():
// a library cannot choose. wearscale's programs (the CLI, the benchmarks) link
// the object library `wearscale::thread_waiting`, whose ELF pre-initialisation
// function, unless the user set OMP_WAIT_POLICY or GOMP_SPINCOUNT, sets
// GOMP_SPINCOUNT to `waiting_spin_count` and starts the program again with it
// (once, before anything else; the child processes it starts inherit it).
// A thread then spins briefly and sleeps if nothing comes: quick on dedicated
// cores, no collapse on shared ones (bench/results/dem.md, "waiting threads chosen by the program"). 3000 spins (about
// 33 µs of `pause` on the 2-vCPU KVM host of bench/results/dem.md, "how long a waiting thread spins") outlast
// the few-µs gaps between a time step's regions and most of the threads'
// imbalance at its barriers; a thread that sleeps there costs ~50 µs to wake.
// The Python package does the same from its __init__.py.
#include <string>

namespace wearscale {

/// Spins of a waiting thread before it sleeps, as wearscale's programs set it
/// (GOMP_SPINCOUNT's text).
inline constexpr char waiting_spin_count[] = "3000";

/// What this process's waiting threads do and who chose it, e.g. "spin 3000
/// times, then sleep (GOMP_SPINCOUNT=3000, set by wearscale)".
std::string thread_waiting();

namespace detail {
/// The variable that marks GOMP_SPINCOUNT as set by the pre-initialisation.
inline constexpr char thread_waiting_marker[] = "WEARSCALE_THREAD_WAITING";
}  // namespace detail

}  // namespace wearscale
