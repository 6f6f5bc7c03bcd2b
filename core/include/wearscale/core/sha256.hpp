#pragma once
// SHA-256 of bytes, as 64 lowercase hex digits: e.g. the key of cached LAMMPS
// results (every input hashed, so a changed input never reuses a result) and the
// checksum of checkpoints.
// Computed by OpenSSL's EVP interface.
#include <memory>
#include <string>
#include <string_view>

namespace wearscale {

/// Incremental SHA-256 (FIPS 180-4).
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  void update(std::string_view bytes);
  /// Adds a length-prefixed field, so ("ab","c") and ("a","bc") differ.
  void field(std::string_view bytes);
  /// The digest as hex; the object must not be updated afterwards.
  std::string hex();

 private:
  struct Context;
  std::unique_ptr<Context> ctx_;
};

/// SHA-256 of `bytes` as hex.
std::string sha256_hex(std::string_view bytes);

}  // namespace wearscale
