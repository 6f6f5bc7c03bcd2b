#pragma once
// A scale of the multiscale model, implemented by a named backend. It declares
// what it consumes and provides; the pipeline orders scales by those
// declarations and runs them.
#include <memory>
#include <string>
#include <vector>

#include "wearscale/core/registry.hpp"
#include "wearscale/coupling/exchange.hpp"
#include "wearscale/coupling/run_context.hpp"
#include "wearscale/io/config.hpp"

namespace wearscale::coupling {

class Scale {
 public:
  virtual ~Scale() = default;
  virtual std::vector<Key> consumes() const = 0;
  virtual std::vector<Key> provides() const = 0;
  /// Reads its inputs from `exchange`, computes, puts every key of provides().
  virtual void run(Exchange& exchange, RunContext& context) = 0;
  /// Under mpirun: whether it farms ensembles over the ranks
  /// (mpi::farm_described); a pipeline with such a scale runs on rank 0 while
  /// the other ranks serve it.
  virtual bool farms_ensembles() const { return false; }
  /// The work of run() in some unit common to the backends (about a BEM solve
  /// on a 128² grid), from its keys alone: what a sweep orders its runs by,
  /// the costliest first. 0: negligible or not known.
  virtual double estimated_cost() const { return 0.0; }
};

/// What a backend factory receives. A backend reads all its keys in its
/// factory (so unknown keys are caught before anything runs).
struct ScaleSetup {
  std::string kind;      ///< "molecular", "nano", "macro"
  std::string backend;   ///< name within the kind
  Config section;        ///< the [scale.<kind>] table
  Config root;           ///< the whole case ([materials], ...)
  Provenance provenance() const { return {kind, backend, section.to_json()}; }
};

using ScaleRegistry = Registry<Scale, const ScaleSetup&>;

/// Every backend of the build, each registered by its WEARSCALE_BACKEND line.
const ScaleRegistry& scale_registry();

}  // namespace wearscale::coupling

/// The registration of a backend, beside its class in coupling/src/backends/
/// and inside namespace wearscale::coupling; the body adds it to `registry`:
///
///   WEARSCALE_BACKEND(macro_hertz) {
///     registry.add({"macro", "hertz", "one line", {consumes...}, {provides...}},
///                  [](const ScaleSetup& s) { return std::make_unique<MacroHertz>(s); });
///   }
///
/// The build collects these lines (cmake/WearscaleRegistrations.cmake) into
/// scale_registry(): a new backend is one new file and nothing else.
#define WEARSCALE_BACKEND(name)                             \
  namespace registered {                                    \
  void add_##name(ScaleRegistry& registry);                 \
  }                                                         \
  void registered::add_##name(ScaleRegistry& registry)
