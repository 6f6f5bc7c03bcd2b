#pragma once
// Okabe & Ito's colour-blind-safe palette (Color Universal Design, 2008) for
// the figures' categories, and its tints for filled regions under lines.
#include <string>
#include <string_view>

namespace wearscale::coupling::okabe_ito {

inline constexpr const char* black = "#000000";
inline constexpr const char* orange = "#E69F00";
inline constexpr const char* sky_blue = "#56B4E9";
inline constexpr const char* bluish_green = "#009E73";
inline constexpr const char* yellow = "#F0E442";
inline constexpr const char* blue = "#0072B2";
inline constexpr const char* vermillion = "#D55E00";
inline constexpr const char* reddish_purple = "#CC79A7";

/// `colour` ("#RRGGBB") mixed with white, `fraction` ∈ [0, 1] of the colour
/// kept (1: the colour, 0: white), each channel rounded: "#RRGGBB".
/// std::invalid_argument for anything but "#RRGGBB" or a fraction outside [0, 1].
std::string tint(std::string_view colour, double fraction);

}  // namespace wearscale::coupling::okabe_ito
