#include "wearscale/io/library_versions.hpp"

#include <fftw3.h>
#include <hdf5.h>
#include <omp.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

namespace wearscale {

std::vector<std::pair<std::string, std::string>> library_versions() {
  unsigned maj = 0, min = 0, rel = 0;
  H5get_libversion(&maj, &min, &rel);
  return {
      {"FFTW", fftw_version},
      {"HDF5", fmt::format("{}.{}.{}", maj, min, rel)},
      {"toml++", fmt::format("{}.{}.{}", TOML_LIB_MAJOR, TOML_LIB_MINOR, TOML_LIB_PATCH)},
      {"fmt", fmt::format("{}.{}.{}", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100)},
      {"nlohmann-json", fmt::format("{}.{}.{}", NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
                                    NLOHMANN_JSON_VERSION_PATCH)},
      {"OpenMP", fmt::format("{} ({} threads)", _OPENMP, omp_get_max_threads())},
  };
}

}  // namespace wearscale
