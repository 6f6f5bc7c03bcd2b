#include "wearscale/coupling/backend_keys.hpp"

#include "wearscale/coupling/scale.hpp"

namespace wearscale::coupling {

Schema backend_schema(const std::string& kind, const std::string& name) {
  const BackendInfo& info = scale_registry().info(kind, name);
  Schema rows{{"scale." + kind + ".backend", "choice", name, "", "", "the backend of the scale", ""}};
  if (info.keys)
    for (auto& row : info.keys()) rows.push_back(std::move(row));
  return rows;
}

}  // namespace wearscale::coupling
