// Fuzzes the checkpoint reader on file images: any bytes are either refused
// (InputError: not a checkpoint, another format, damaged, another case) or
// restore exactly a state whose checksum matched. Nothing else may happen.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/hdf5_file.hpp"

using namespace wearscale;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view image(reinterpret_cast<const char*>(data), size);
  try {
    // Through the guard, as Checkpointer::load(): a file that crashes HDF5 is refused. The
    // fingerprint is the file's own, so that mutations reach the checksum and the states.
    Checkpointer checkpoints("fuzz-checkpoint.h5", "", {0.0, 0});
    H5Reader::guarded_image(image, "fuzz-checkpoint.h5", [&](const H5Reader& file) {
      checkpoints = Checkpointer("fuzz-checkpoint.h5", file.string_attribute_if("/", "fingerprint").value_or(""),
                                 {0.0, 0});
      checkpoints.load(file);
    });
    for (const char* owner : {"macro/bem-pin-on-disc", "dem/patch_test", "o"})
      if (const CheckpointState* s = checkpoints.restored(owner); s != nullptr && s->step < 0) std::abort();
  } catch (const InputError&) {
  }
  return 0;
}
