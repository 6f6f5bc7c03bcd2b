// Fuzzes the HDF5 topography reader on file images: any bytes give a finite
// height grid of positive size, or InputError naming the problem (a damaged
// file, a missing or malformed dataset or attribute, a declared size beyond
// the memory limit). A crash, another exception or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "topography_checks.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/topography_io.hpp"

using namespace wearscale;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view image(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    // Through the guard, as every reader of a user's file: a file that crashes HDF5 is refused.
    H5Reader::guarded_image(image, "fuzz.h5", [&](const H5Reader& file) {
      fuzz::check_topography(bem::read_topography_h5(file, bem::default_surface_dataset, fuzz::given_size(data)));
      (void)file.number_attribute_if(bem::default_surface_dataset, "k_s");  // the generation parameters, alike
    });
  } catch (const InputError&) {
  }
  return 0;
}
