#include "wearscale/dem/worn_particles.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace wearscale::dem {

namespace {
// Each particle's bonded neighbours as sorted ids, in CSR form by index.
void neighbor_ids(const Particles& p, const Box& box, const BondCriterion& bond, std::vector<std::size_t>& offset,
                  std::vector<std::int64_t>& ids) {
  const auto pairs = bonded_pairs(p, box, bond);
  offset.assign(p.size() + 1, 0);
  for (const auto& [i, j] : pairs) {
    ++offset[i + 1];
    ++offset[j + 1];
  }
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  ids.resize(offset.back());
  std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
  for (const auto& [i, j] : pairs) {
    ids[fill[i]++] = p.id[j];
    ids[fill[j]++] = p.id[i];
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    std::sort(ids.begin() + static_cast<std::ptrdiff_t>(offset[i]), ids.begin() + static_cast<std::ptrdiff_t>(offset[i + 1]));
}
}  // namespace

WornParticles::WornParticles(const Particles& p, const Box& box, BondCriterion bond) : bond_(std::move(bond)) {
  std::vector<std::size_t> offset;
  std::vector<std::int64_t> ids;
  neighbor_ids(p, box, bond_, offset, ids);
  // Re-index by sorted id, so that later particle sets (reordered, carved)
  // find their reference by identity.
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  ids_.reserve(p.size());
  offset_.assign(1, 0);
  neighbor_.reserve(ids.size());
  for (std::size_t i : order) {
    ids_.push_back(p.id[i]);
    neighbor_.insert(neighbor_.end(), ids.begin() + static_cast<std::ptrdiff_t>(offset[i]),
                     ids.begin() + static_cast<std::ptrdiff_t>(offset[i + 1]));
    offset_.push_back(neighbor_.size());
  }
}

std::size_t WornParticles::slot(std::int64_t id) const {
  const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
  return it != ids_.end() && *it == id ? static_cast<std::size_t>(it - ids_.begin()) : ids_.size();
}

std::size_t WornParticles::initial_neighbors(std::int64_t id) const {
  const std::size_t s = slot(id);
  return s == ids_.size() ? 0 : offset_[s + 1] - offset_[s];
}

std::vector<double> WornParticles::lost_fraction(const Particles& p, const Box& box) const {
  std::vector<std::size_t> offset;
  std::vector<std::int64_t> now;
  neighbor_ids(p, box, bond_, offset, now);
  std::vector<double> lost(p.size(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t s = slot(p.id[i]);
    if (s == ids_.size()) continue;
    const auto b0 = neighbor_.begin() + static_cast<std::ptrdiff_t>(offset_[s]);
    const auto e0 = neighbor_.begin() + static_cast<std::ptrdiff_t>(offset_[s + 1]);
    const auto initial = static_cast<std::size_t>(e0 - b0);
    if (initial == 0) continue;
    // Reference neighbours still bonded: the intersection of two sorted lists.
    std::size_t kept = 0;
    auto a = b0;
    auto b = now.begin() + static_cast<std::ptrdiff_t>(offset[i]);
    const auto e1 = now.begin() + static_cast<std::ptrdiff_t>(offset[i + 1]);
    while (a != e0 && b != e1) {
      if (*a < *b) {
        ++a;
      } else if (*b < *a) {
        ++b;
      } else {
        ++kept;
        ++a;
        ++b;
      }
    }
    lost[i] = static_cast<double>(initial - kept) / static_cast<double>(initial);
  }
  return lost;
}

std::vector<bool> WornParticles::worn(const Particles& p, const Box& box) const {
  const auto lost = lost_fraction(p, box);
  std::vector<bool> out(lost.size());
  for (std::size_t i = 0; i < lost.size(); ++i) out[i] = lost[i] > 0.5;  // more than half (§7.2)
  return out;
}

std::size_t WornParticles::count_worn(const Particles& p, const Box& box) const {
  const auto w = worn(p, box);
  return static_cast<std::size_t>(std::count(w.begin(), w.end(), true));
}

}  // namespace wearscale::dem
