#pragma once
// The saved state of a resumable solver: named arrays of doubles (kept bit
// for bit) and texts. A solver fills one and restores from one; where and how
// it is stored (io/checkpoint.hpp: an HDF5 file with a checksum) is not the
// solver's business.
#include <map>
#include <span>
#include <string>
#include <vector>

namespace wearscale {

/// The saved state of one owner: named arrays of doubles (bit-exact) and texts.
class CheckpointState {
 public:
  long step = 0;  ///< the owner's step count when saved

  void put(const std::string& name, std::span<const double> values);
  void put(const std::string& name, double value);
  void put_text(const std::string& name, std::string text);

  bool has(const std::string& name) const;
  /// InputError naming the entry if the checkpoint lacks it (a file of another version).
  const std::vector<double>& array(const std::string& name) const;
  /// An array of exactly one value.
  double scalar(const std::string& name) const;
  /// A scalar that must be a whole number within [low, high] (a step count, a
  /// counter), checked before it becomes an integer (NaN or 1e300 convert to
  /// nothing); InputError naming the entry and the checkpoint otherwise.
  long count(const std::string& name, double low, double high) const;
  const std::string& text(const std::string& name) const;

  const std::map<std::string, std::vector<double>>& arrays() const { return arrays_; }
  const std::map<std::string, std::string>& texts() const { return texts_; }
  /// Where it was read from (for messages).
  std::string origin = "checkpoint";

 private:
  std::map<std::string, std::vector<double>> arrays_;
  std::map<std::string, std::string> texts_;
};

/// "" if `value` is a whole number within [low, high], else the problem naming
/// `name` (for counts restored from a checkpoint and the same counts computed).
std::string count_problem(const std::string& name, double value, double low, double high);

}  // namespace wearscale
