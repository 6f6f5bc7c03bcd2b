#pragma once
// The Levenshtein distance of two words: how "did you mean" messages find the
// key or name closest to a misspelt one.
#include <cstddef>
#include <string_view>

namespace wearscale {

/// Insertions, deletions and substitutions that turn `a` into `b`.
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace wearscale
