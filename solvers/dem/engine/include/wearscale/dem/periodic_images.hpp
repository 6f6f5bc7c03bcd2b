#pragma once
// The periodic images a pair search considers: shifts of up to K_a box
// lengths along each periodic axis a, K_a = ⌈cut / L_a⌉, so that a box as thin
// as one particle along an axis still meets every image of every neighbour
// within the cutoff (what LAMMPS' ghost atoms do). An image is stored in one
// byte, the index of its shift (s_x, s_y, s_z) in a table of at most 255.
#include <array>
#include <cstddef>
#include <cstdint>

#include "wearscale/dem/box.hpp"

namespace wearscale::dem {

struct PeriodicImages {
  static constexpr int max_count = 255;

  /// K per axis: shifts −K…K (0 on open axes).
  std::array<int, 3> reach{1, 1, 1};

  /// The images within `cut` of a box whose positions are wrapped into it.
  /// InputError when they would be more than max_count.
  static PeriodicImages within(const Box& box, double cut);

  int count() const { return width(0) * width(1) * width(2); }
  std::uint8_t index(int sx, int sy, int sz) const {
    return static_cast<std::uint8_t>((sx + reach[0]) + width(0) * ((sy + reach[1]) + width(1) * (sz + reach[2])));
  }
  /// The unshifted image.
  std::uint8_t zero() const { return index(0, 0, 0); }
  /// The opposite shift: the image of i seen from j.
  std::uint8_t mirrored(std::uint8_t s) const { return static_cast<std::uint8_t>(count() - 1 - s); }
  /// The shift in box lengths of image s.
  std::array<int, 3> shift(std::uint8_t s) const;
  /// The index of a shift in box lengths, or −1 when it lies beyond the reach.
  int find(const std::array<int, 3>& s) const;
  /// The separation offsets (s_x L_x, s_y L_y, s_z L_z) of every image, count() of them.
  void vectors(const Box& box, Vec3* out) const;

  bool operator==(const PeriodicImages&) const = default;

 private:
  int width(std::size_t a) const { return 2 * reach[a] + 1; }
};

}  // namespace wearscale::dem
