#include "wearscale/core/mpi.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <omp.h>

#ifdef WEARSCALE_MPI
#include <mpi.h>
#endif

namespace wearscale::mpi {

namespace {
// The job (world) as MPI_Init found it; `g_alone` while this process runs a
// farmed task (task_farm.hpp): active(), rank() and size() then say serial.
bool g_active = false;
int g_rank = 0, g_size = 1, g_node_size = 1;
std::atomic<bool> g_alone{false};

#ifdef WEARSCALE_MPI
// A launcher's variables: Open MPI's mpirun, PMI (MPICH, Intel MPI) and PMIx (Slurm's srun).
bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}
#endif
}  // namespace

bool built_with_mpi() {
#ifdef WEARSCALE_MPI
  return true;
#else
  return false;
#endif
}

Session::Session(int& argc, char**& argv) {
#ifdef WEARSCALE_MPI
  if (!launched_by_mpi()) return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  // Errors in MPI calls end the job (the default handler), never return codes left unchecked.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
  MPI_Comm node;  // the ranks that share this node's memory (and cores)
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, g_rank, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &g_node_size);
  MPI_Comm_free(&node);
  g_active = true;
#else
  (void)argc;
  (void)argv;
#endif
}

Session::~Session() {
#ifdef WEARSCALE_MPI
  if (g_active) MPI_Finalize();
#endif
  g_active = false;
  g_rank = 0;
  g_size = 1;
  g_node_size = 1;
}

bool active() { return g_active && !g_alone; }
int rank() { return g_alone ? 0 : g_rank; }
int size() { return g_alone ? 1 : g_size; }
int world_rank() { return g_rank; }
int world_size() { return g_size; }
int node_size() { return g_node_size; }

int default_threads_per_rank() {
  if (g_size <= 1) return 0;
  return std::max(1, omp_get_num_procs() / std::max(1, g_node_size));
}

Alone::Alone() : was_(g_alone.exchange(true)) {}
Alone::~Alone() { g_alone = was_; }

void abort(int code) {
#ifdef WEARSCALE_MPI
  if (g_active && g_size > 1) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

void barrier() {
#ifdef WEARSCALE_MPI
  if (active()) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

void sum(std::span<double> values) {
#ifdef WEARSCALE_MPI
  if (!active() || size() == 1) return;
  // Gather every rank's values and add them in rank order on every rank: the
  // same bits whatever the reduction tree of the MPI library.
  const int n = static_cast<int>(values.size());
  thread_local std::vector<double> all;  // kept: no allocation per call in solver loops
  all.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(g_size));
  MPI_Allgather(values.data(), n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, MPI_COMM_WORLD);
  for (int k = 0; k < n; ++k) {
    double s = 0.0;
    for (int r = 0; r < g_size; ++r) s += all[static_cast<std::size_t>(r) * static_cast<std::size_t>(n) + k];
    values[static_cast<std::size_t>(k)] = s;
  }
#else
  (void)values;
#endif
}

double sum(double local) {
  sum(std::span<double>(&local, 1));
  return local;
}

long long sum(long long local) {
#ifdef WEARSCALE_MPI
  if (active() && size() > 1) {
    long long total = 0;
    MPI_Allreduce(&local, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    return total;
  }
#endif
  return local;
}

double max(double local) {
#ifdef WEARSCALE_MPI
  if (active() && size() > 1) {
    double m = local;
    MPI_Allreduce(&local, &m, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return m;
  }
#endif
  return local;
}

namespace {
#ifdef WEARSCALE_MPI
// Every rank's count `n` on rank 0, their offsets in rank order and their
// total (collective): the layout of a gather or a scatter of uneven parts.
struct RankParts {
  std::vector<int> counts, offsets;
  long long total = 0;
};
RankParts rank_parts(int n) {
  RankParts parts{std::vector<int>(static_cast<std::size_t>(g_size)), std::vector<int>(static_cast<std::size_t>(g_size))};
  MPI_Gather(&n, 1, MPI_INT, parts.counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  for (int r = 0; r < g_size; ++r) {
    parts.offsets[static_cast<std::size_t>(r)] = static_cast<int>(parts.total);
    parts.total += parts.counts[static_cast<std::size_t>(r)];
  }
  return parts;
}

void reduce(std::span<double> values, MPI_Op op) {
  if (active() && size() > 1 && !values.empty())
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, op, MPI_COMM_WORLD);
}
#endif
}  // namespace

void max(std::span<double> values) {
#ifdef WEARSCALE_MPI
  reduce(values, MPI_MAX);
#else
  (void)values;
#endif
}

void min(std::span<double> values) {
#ifdef WEARSCALE_MPI
  reduce(values, MPI_MIN);
#else
  (void)values;
#endif
}

void gather(std::span<const double> local, std::span<double> all) {
#ifdef WEARSCALE_MPI
  if (active() && size() > 1) {
    const int n = static_cast<int>(local.size());
    const RankParts parts = rank_parts(n);
    if (g_rank == 0 && parts.total != static_cast<long long>(all.size()))
      throw std::invalid_argument("mpi::gather: the ranks' values do not fill the destination");
    MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), parts.counts.data(), parts.offsets.data(), MPI_DOUBLE, 0,
                MPI_COMM_WORLD);
    return;
  }
#endif
  if (all.size() != local.size()) throw std::invalid_argument("mpi::gather: the values do not fill the destination");
  std::copy(local.begin(), local.end(), all.begin());
}

void scatter(std::span<const double> all, std::span<double> local) {
#ifdef WEARSCALE_MPI
  if (active() && size() > 1) {
    const int n = static_cast<int>(local.size());
    const RankParts parts = rank_parts(n);
    if (g_rank == 0 && parts.total != static_cast<long long>(all.size()))
      throw std::invalid_argument("mpi::scatter: the ranks' parts do not add up to the values scattered");
    MPI_Scatterv(all.data(), parts.counts.data(), parts.offsets.data(), MPI_DOUBLE, local.data(), n, MPI_DOUBLE, 0,
                 MPI_COMM_WORLD);
    return;
  }
#endif
  if (all.size() != local.size()) throw std::invalid_argument("mpi::scatter: the values do not fill the destination");
  std::copy(all.begin(), all.end(), local.begin());
}

void broadcast(std::span<double> values) {
#ifdef WEARSCALE_MPI
  if (active() && size() > 1)
    MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
#else
  (void)values;
#endif
}

void broadcast(std::string& text) {
#ifdef WEARSCALE_MPI
  if (active() && size() > 1) {
    unsigned long long length = text.size();
    MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    text.resize(static_cast<std::size_t>(length));
    MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD);
  }
#else
  (void)text;
#endif
}

void refuse_together(const std::function<void()>& checks) {
  if (size() == 1) {
    checks();
    return;
  }
  std::string message;
  bool refused = false;
  try {
    checks();
  } catch (const InputError& e) {
    message = e.what();
    refused = true;
  }
  // The lowest rank that refused, as size() − rank (0: none refused).
  const double lowest = max(refused ? static_cast<double>(size() - rank()) : 0.0);
  if (lowest == 0.0) return;
  const bool speaks = refused && static_cast<double>(size() - rank()) == lowest;
  throw JointRefusal(speaks ? message : std::string(), speaks);
}

}  // namespace wearscale::mpi
