#include "wearscale/dem/hcp_lattice.hpp"

#include <cmath>

namespace wearscale::dem {

Vec3 HcpLattice::cell() const {
  return {spacing, std::sqrt(3.0) * spacing, std::sqrt(8.0 / 3.0) * spacing};
}

std::vector<Vec3> HcpLattice::sites() const {
  static constexpr double basis[4][3] = {
      {0.0, 0.0, 0.0}, {0.5, 0.5, 0.0}, {0.5, 5.0 / 6.0, 0.5}, {0.0, 1.0 / 3.0, 0.5}};
  const Vec3 c = cell();
  std::vector<Vec3> out;
  out.reserve(4 * static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& b : basis)
          out.push_back({(i + b[0]) * c.x, (j + b[1]) * c.y, (k + b[2]) * c.z});
  return out;
}

Box HcpLattice::box() const {
  const Vec3 c = cell();
  Box b;
  b.lo = {0.0, 0.0, -0.25 * c.z};
  b.hi = {nx * c.x, ny * c.y, (nz - 0.25) * c.z};
  b.periodic = {true, true, true};
  return b;
}

}  // namespace wearscale::dem
