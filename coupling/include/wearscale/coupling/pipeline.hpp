#pragma once
// Orders the scales of a case so that every quantity is produced before it is
// consumed, and runs them.
#include <memory>
#include <string>
#include <vector>

#include "wearscale/coupling/scale.hpp"

namespace wearscale::coupling {

class Pipeline {
 public:
  /// Adds a scale under its id ("nano/analytic").
  void add(std::string id, std::unique_ptr<Scale> scale);

  /// Topological order from the declarations. InputError if a consumed
  /// quantity has no provider, if two scales provide the same quantity, or if
  /// the declarations form a cycle; each message names the scales involved.
  void order();
  /// Ids in run order (after order()).
  std::vector<std::string> ids() const;

  /// A scale farms ensembles over the ranks of an mpirun job (Scale::farms_ensembles).
  bool farms_ensembles() const;
  /// The sum of its scales' Scale::estimated_cost().
  double estimated_cost() const;

  /// Runs every scale in order; checks each provided what it declared.
  void run(Exchange& exchange, RunContext& context);

 private:
  struct Node {
    std::string id;
    std::unique_ptr<Scale> scale;
  };
  std::vector<Node> nodes_;
  bool ordered_ = false;
};

}  // namespace wearscale::coupling
