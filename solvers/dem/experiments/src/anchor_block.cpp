#include "wearscale/dem/anchor_block.hpp"

#include <cmath>
#include <numbers>

#include "wearscale/dem/hcp_lattice.hpp"

namespace wearscale::dem {

namespace {
// The deck's deterministic velocity hash: fract(sin(a·x) 43758.5453).
double hashed(double a, double b, double c, const Vec3& x) {
  const double h = std::sin(a * x.x + b * x.y + c * x.z) * 43758.5453;
  return 2.0 * (h - std::floor(h)) - 1.0;
}
}  // namespace

Simulation make_anchor_block(const AnchorBlock& spec) {
  const double d = 1.0, rho = 6.0 / std::numbers::pi, v0 = 0.1;
  HcpLattice lattice{0.995 * d, spec.cells, spec.cells, spec.cells};
  Box box = lattice.box();
  box.periodic = {true, true, false};
  const double c = lattice.cell().z;
  const double wall_lo = box.lo.z + c, wall_hi = box.hi.z - c;

  Particles p;
  const auto sites = lattice.sites();
  p.reserve(sites.size());
  std::vector<std::size_t> bottom, top;
  for (const auto& x : sites) {
    Sphere s{x, 0.5 * d, rho, {}, 0, 0};
    const bool low = x.z < wall_lo, high = x.z > wall_hi;
    if (!low && !high)
      s.velocity = {v0 * hashed(12.9898, 78.2330, 37.7190, x), v0 * hashed(39.3468, 11.1350, 83.1550, x),
                    v0 * hashed(73.1560, 52.2350, 9.1510, x)};
    const std::size_t i = p.add(s);
    if (low) bottom.push_back(i);
    if (high) top.push_back(i);
  }
  HookeLaw law{2.0e4, 1.0e4, 50.0, 25.0, 0.5};
  NeighborSettings neighbors{0.1 * d, spec.rebuild_every, false};
  neighbors.renumber_every = spec.renumber_every;
  Simulation sim(std::move(p), box, law, neighbors);
  sim.add_wall(std::move(bottom), WallMotion::fixed());
  sim.add_wall(std::move(top), WallMotion::fixed());
  sim.set_time_step(0.05 * std::sqrt(2.0 * 1.0 / 2.0e4));
  return sim;
}

}  // namespace wearscale::dem
