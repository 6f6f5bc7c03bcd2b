#pragma once
// A scale of the multiscale model, implemented by a named backend. Its class
// declares once what its kind consumes and provides (Ports); an instance
// gives the keys of its case (consumes(), provides()), by which the pipeline
// orders the scales and runs them.
#include <memory>
#include <string>
#include <vector>

#include "wearscale/core/registry.hpp"
#include "wearscale/coupling/exchange.hpp"
#include "wearscale/coupling/run_context.hpp"
#include "wearscale/io/config.hpp"

namespace wearscale::coupling {

/// What a backend kind exchanges, declared once in its class as
///   static inline const Ports ports{{consumed...}, {provided...}};
/// each a quantity with its subjects in words ("pin/disc", "<each material of
/// [materials]>"). `wearscale backends` lists them; the instance's consumes()
/// and provides() give its case's keys of those quantities, and the registry
/// refuses an instance that exchanges a quantity its kind does not declare.
struct Ports {
  std::vector<Key> consumes, provides;
};

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

/// The scale backends of the build: the one registry template
/// (core/registry.hpp) of scales, by kind and name.
class ScaleRegistry : public Registry<Scale, const ScaleSetup&> {
 public:
  using NamedRegistry::add;
  /// Registers backend class B (made by B(setup)) under kind/name, with
  /// what it exchanges from B::ports and the rows of its keys, `keys()`
  /// (its key table's schema("scale.<kind>"); no rows: it reads none there).
  template <class B>
  void add(std::string kind, std::string name, std::string summary, std::function<Schema()> keys) {
    add({std::move(kind), std::move(name), std::move(summary), texts(B::ports.consumes), texts(B::ports.provides),
         std::move(keys)},
        [](const ScaleSetup& s) -> std::unique_ptr<Scale> { return checked(std::make_unique<B>(s), B::ports, s); });
  }

 private:
  static std::vector<std::string> texts(const std::vector<Key>& keys);
  /// `scale`, after checking that its keys' quantities are those its kind declares (std::logic_error if not).
  static std::unique_ptr<Scale> checked(std::unique_ptr<Scale> scale, const Ports& ports, const ScaleSetup& setup);
};

/// Every backend of the build, each registered by its WEARSCALE_BACKEND line.
const ScaleRegistry& scale_registry();

}  // namespace wearscale::coupling

/// The registration of a backend, beside its class in coupling/src/backends/
/// and inside namespace wearscale::coupling; the body adds it to `registry`:
///
///   WEARSCALE_BACKEND(macro_hertz) {
///     registry.add<MacroHertz>("macro", "hertz", "one line", [] { return hertz_keys().schema("scale.macro"); });
///   }
///
/// The build collects these lines (cmake/WearscaleRegistrations.cmake) into
/// scale_registry(): a new backend is one new file and nothing else.
#define WEARSCALE_BACKEND(name)                             \
  namespace registered {                                    \
  void add_##name(ScaleRegistry& registry);                 \
  }                                                         \
  void registered::add_##name(ScaleRegistry& registry)
