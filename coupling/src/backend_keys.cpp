#include "wearscale/coupling/backend_keys.hpp"

#include <map>
#include <utility>

#include "wearscale/coupling/scale.hpp"

namespace wearscale::coupling {

namespace {
std::map<std::pair<std::string, std::string>, std::function<Schema()>>& schemas() {
  static std::map<std::pair<std::string, std::string>, std::function<Schema()>> all;
  return all;
}
}  // namespace

void add_backend_keys(const std::string& kind, const std::string& name, std::function<Schema()> schema) {
  schemas()[{kind, name}] = std::move(schema);
}

bool has_backend_keys(const std::string& kind, const std::string& name) {
  (void)scale_registry();  // the backends' registrations add their key tables
  return schemas().count({kind, name}) != 0;
}

Schema backend_schema(const std::string& kind, const std::string& name) {
  if (!has_backend_keys(kind, name)) return {};
  Schema rows{{"scale." + kind + ".backend", "choice", name, "", "", "the backend of the scale", ""}};
  for (auto& row : schemas().at({kind, name})()) rows.push_back(std::move(row));
  return rows;
}

}  // namespace wearscale::coupling
