#include "wearscale/coupling/pipeline.hpp"

#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::coupling {

void Pipeline::add(std::string id, std::unique_ptr<Scale> scale) {
  nodes_.push_back({std::move(id), std::move(scale)});
  ordered_ = false;
}

void Pipeline::order() {
  std::map<Key, std::size_t> provider;
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    for (const auto& k : nodes_[i].scale->provides()) {
      if (auto it = provider.find(k); it != provider.end())
        throw InputError(fmt::format("{} is provided by two scales, {} and {}; keep one of them in the case",
                                     k.to_string(), nodes_[it->second].id, nodes_[i].id));
      provider.emplace(k, i);
    }
  for (const auto& n : nodes_)
    for (const auto& k : n.scale->consumes())
      if (provider.count(k) == 0)
        throw InputError(fmt::format("{} needs {}, but no scale of this case provides it (add a [scale.*] "
                                     "table whose backend provides it; `wearscale backends` lists them)",
                                     n.id, k.to_string()));

  // Kahn's algorithm, stable in declaration order.
  std::vector<std::size_t> indegree(nodes_.size(), 0);
  std::vector<std::vector<std::size_t>> users(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    for (const auto& k : nodes_[i].scale->consumes()) {
      const auto p = provider.at(k);
      users[p].push_back(i);
      ++indegree[i];
    }
  std::vector<std::size_t> sequence;
  std::vector<bool> done(nodes_.size(), false);
  while (sequence.size() < nodes_.size()) {
    bool progressed = false;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (done[i] || indegree[i] != 0) continue;
      done[i] = true;
      sequence.push_back(i);
      for (auto u : users[i]) --indegree[u];
      progressed = true;
      break;
    }
    if (!progressed) {
      std::vector<std::string> cycle;
      for (std::size_t i = 0; i < nodes_.size(); ++i)
        if (!done[i]) cycle.push_back(nodes_[i].id);
      throw InputError(fmt::format("the scales {} consume each other's quantities in a cycle", fmt::join(cycle, ", ")));
    }
  }
  std::vector<Node> sorted;
  for (auto i : sequence) sorted.push_back(std::move(nodes_[i]));
  nodes_ = std::move(sorted);
  ordered_ = true;
}

std::vector<std::string> Pipeline::ids() const {
  std::vector<std::string> out;
  for (const auto& n : nodes_) out.push_back(n.id);
  return out;
}

bool Pipeline::farms_ensembles() const {
  for (const auto& n : nodes_)
    if (n.scale->farms_ensembles()) return true;
  return false;
}

double Pipeline::estimated_cost() const {
  double cost = 0.0;
  for (const auto& n : nodes_) cost += n.scale->estimated_cost();
  return cost;
}

void Pipeline::run(Exchange& exchange, RunContext& context) {
  if (!ordered_) order();
  for (auto& n : nodes_) {
    n.scale->run(exchange, context);
    for (const auto& k : n.scale->provides())
      if (!exchange.contains(k))
        throw std::logic_error(fmt::format("{} declared {} but did not provide it", n.id, k.to_string()));
  }
}

}  // namespace wearscale::coupling
