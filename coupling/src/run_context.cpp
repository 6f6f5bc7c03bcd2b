#include "wearscale/coupling/run_context.hpp"

namespace wearscale::coupling {

Checkpointer& RunContext::checkpoints() { return checkpoints_ != nullptr ? *checkpoints_ : no_checkpoints_; }

void RunContext::report(const std::string& name, double value, const std::string& unit,
                        const std::string& description) {
  results_[name] = {{"value", value}, {"unit", unit}, {"description", description}};
}

void RunContext::draw_figures() {
  std::vector<Figure> figures;
  figures.swap(figures_);
  for (auto& file : coupling::draw_figures(dir_, figures)) add_file(file);
}

}  // namespace wearscale::coupling
