// wearscale._study_keys: the keys of any registered study's case as its key
// tables declare them (the rows of its schema), and the defaults the
// bindings take from there, so that no binding writes a case default twice.
#include <stdexcept>

#include "bindings.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::python {

namespace py = pybind11;

std::string study_default(const std::string& study, const std::string& key) {
  const auto schema = studies::study_registry().create(study)->schema();
  const auto* spec = studies::find_key(schema, key);
  if (spec == nullptr || spec->fallback.empty()) throw std::logic_error(study + " declares no default for " + key);
  return spec->fallback;
}

void bind_study_keys(py::module_& m) {
  m.def(
      "_study_keys",
      [](const std::string& study) {
        py::list out;
        for (const auto& row : studies::study_registry().create(study)->schema()) {
          py::dict d;
          d["key"] = row.key;
          d["type"] = row.type;
          d["allowed"] = row.range;
          d["unit"] = row.unit;
          d["default"] = row.fallback;
          out.append(d);
        }
        return out;
      },
      py::arg("study"),
      "The keys of a registered study's case (`contact`, `dem/rough_shear`, `wearmap/rough`, ...) as its key "
      "tables declare them: key, type, allowed values, unit, default in words.");
}

}  // namespace wearscale::python
