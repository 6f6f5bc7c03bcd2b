// Fuzzes the HDF5 strength-table reader on file images: any bytes give a
// valid table (whose law then evaluates to finite, non-negative strengths),
// or InputError naming the problem (types, shapes, units, provenance
// attributes of h5py's or any kind).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "strength_table_checks.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/strength_table_file.hpp"

using namespace wearscale;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view image(reinterpret_cast<const char*>(data), size);
  try {
    // Through the guard, as every reader of a user's file: a file that crashes HDF5 is refused.
    fuzz::check_strength_table(H5Reader::guarded_image(image, "fuzz.h5", materials::parse_strength_table_h5));
  } catch (const InputError&) {
  } catch (const NumericalError&) {
    // a pressure rounding just outside the table's range: a reported failure, not a crash
  }
  return 0;
}
