#include "wearscale/dem/rigid_fit.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/simulation.hpp"

namespace wearscale::dem {

RigidFit rigid_fit(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  const auto n = a.size();
  if (n == 0 || b.size() != n) return {};
  Eigen::Vector3d ca = Eigen::Vector3d::Zero(), cb = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    ca += Eigen::Vector3d(a[k].x, a[k].y, a[k].z);
    cb += Eigen::Vector3d(b[k].x, b[k].y, b[k].z);
  }
  ca /= static_cast<double>(n);
  cb /= static_cast<double>(n);
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < n; ++k)
    h += (Eigen::Vector3d(a[k].x, a[k].y, a[k].z) - ca) * (Eigen::Vector3d(b[k].x, b[k].y, b[k].z) - cb).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
  double misfit = 0.0, moved = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d pa(a[k].x, a[k].y, a[k].z), pb(b[k].x, b[k].y, b[k].z);
    misfit += (r * (pa - ca) + cb - pb).squaredNorm();
    moved += (pb - cb - (pa - ca)).squaredNorm();
  }
  RigidFit out;
  out.residual = moved > 0.0 ? std::sqrt(misfit / moved) : 0.0;
  out.angle_y = std::atan2(r(0, 2), r(0, 0));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.rotation[static_cast<std::size_t>(3 * i + j)] = r(i, j);
  out.from = {ca.x(), ca.y(), ca.z()};
  out.to = {cb.x(), cb.y(), cb.z()};
  return out;
}

namespace {
std::vector<Vec3> unwrapped(const Particles& p, const Box& box, const std::vector<std::size_t>& set) {
  const Vec3 l = box.length();
  std::vector<Vec3> x;
  x.reserve(set.size());
  for (std::size_t i : set) {
    Vec3 xi = p.position[i];
    for (int a = 0; a < 3; ++a) xi[a] += p.image[i][static_cast<std::size_t>(a)] * l[a];
    x.push_back(xi);
  }
  return x;
}

}  // namespace

std::vector<Vec3> unwrapped_positions(const Simulation& sim, const std::vector<std::size_t>& set) {
  return unwrapped(sim.particles(), sim.box(), set);
}

std::vector<Vec3> unwrapped_positions(const Engine& engine, const std::vector<std::size_t>& set) {
  return unwrapped(engine.particles(), engine.box(), set);
}

}  // namespace wearscale::dem
