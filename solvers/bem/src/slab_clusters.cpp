#include "wearscale/bem/slab_clusters.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "wearscale/core/mpi.hpp"

namespace wearscale::bem {

namespace {

// A cluster's piece within one slab, positions unwrapped in its own frame,
// where its first point in raster order (its seed) sits at its grid position.
struct Piece {
  long long seed = 0;  // the seed's global raster index i·ny + j
  long long points = 0;
  long long sum_i = 0, sum_j = 0;  // Σ unwrapped positions
  bool spans = false;              // met itself around the cell
};

// What one rank sends rank 0, as doubles (integers below 2^53: exact):
// first row, rows, pieces, edge points; each piece (seed, points, Σi, Σj,
// spans); each contact point of the slab's first and last rows (which: 0 | 1,
// column, piece, unwrapped i, j).
constexpr std::size_t kHeader = 4, kPieceValues = 5, kEdgeValues = 5;

// A slab's pieces: what it sends rank 0, and the piece of each of its points (−1 outside).
struct Labelled {
  std::vector<double> message;
  std::vector<std::int32_t> label;
  std::size_t pieces = 0;
};

Labelled label_rows(const RealField& p, std::size_t first_row, const Grid2D& whole,
                    const std::vector<std::pair<long, long>>& steps) {
  const long rows = static_cast<long>(p.grid().nx), ny = static_cast<long>(whole.ny);
  const long first = static_cast<long>(first_row);
  const auto at = [ny](long row, long j) { return static_cast<std::size_t>(row * ny + ((j % ny) + ny) % ny); };
  // 12 B a point it holds (positions stay within ±(rows + points) < 2^31 for grids up to 16384²).
  std::vector<std::int32_t> label(p.size(), -1);
  std::vector<std::int32_t> seen_i(p.size()), seen_j(p.size());  // unwrapped position where a point was reached
  std::vector<Piece> pieces;
  std::vector<std::pair<long, long>> queue;  // as long as the largest piece
  for (long r0 = 0; r0 < rows; ++r0)
    for (long j0 = 0; j0 < ny; ++j0) {
      const std::size_t k0 = at(r0, j0);
      if (!(p[k0] > 0.0) || label[k0] >= 0) continue;
      const int id = static_cast<int>(pieces.size());
      Piece piece;
      piece.seed = (first + r0) * ny + j0;
      queue.assign(1, {first + r0, j0});
      label[k0] = id;
      seen_i[k0] = static_cast<std::int32_t>(first + r0);
      seen_j[k0] = static_cast<std::int32_t>(j0);
      for (std::size_t head = 0; head < queue.size(); ++head) {
        const auto [ui0, uj0] = queue[head];
        ++piece.points;
        piece.sum_i += ui0;
        piece.sum_j += uj0;
        for (const auto& [di, dj] : steps) {
          const long ui = ui0 + di, uj = uj0 + dj, row = ui - first;  // rows do not wrap within a slab
          if (row < 0 || row >= rows) continue;
          const std::size_t k = at(row, uj);
          if (!(p[k] > 0.0)) continue;
          if (label[k] == id) {
            if (seen_i[k] != ui || seen_j[k] != uj) piece.spans = true;
            continue;
          }
          label[k] = id;
          seen_i[k] = static_cast<std::int32_t>(ui);
          seen_j[k] = static_cast<std::int32_t>(uj);
          queue.emplace_back(ui, uj);
        }
      }
      pieces.push_back(piece);
    }
  std::vector<double> out = {static_cast<double>(first_row), static_cast<double>(rows),
                             static_cast<double>(pieces.size()), 0.0};
  for (const Piece& c : pieces)
    out.insert(out.end(), {static_cast<double>(c.seed), static_cast<double>(c.points), static_cast<double>(c.sum_i),
                           static_cast<double>(c.sum_j), c.spans ? 1.0 : 0.0});
  std::size_t edge = 0;
  for (int which = 0; which < 2 && rows > 0; ++which) {  // a one-row slab lists its row twice
    const long row = which == 0 ? 0 : rows - 1;
    for (long j = 0; j < ny; ++j) {
      const std::size_t k = at(row, j);
      if (label[k] < 0) continue;
      out.insert(out.end(), {static_cast<double>(which), static_cast<double>(j), static_cast<double>(label[k]),
                             static_cast<double>(seen_i[k]), static_cast<double>(seen_j[k])});
      ++edge;
    }
  }
  out[3] = static_cast<double>(edge);
  return {std::move(out), std::move(label), pieces.size()};
}

// Pieces joined with their relative positions: a weighted union-find where
// shift[x] is where x's frame origin sits in its parent's frame.
struct Joined {
  std::vector<std::size_t> parent;
  std::vector<std::pair<long long, long long>> shift;
  std::vector<bool> spans;

  explicit Joined(std::size_t n) : parent(n), shift(n, {0, 0}), spans(n, false) {
    std::iota(parent.begin(), parent.end(), std::size_t{0});
  }
  // The root of x and where x's frame origin sits in the root's frame.
  std::pair<std::size_t, std::pair<long long, long long>> find(std::size_t x) {
    std::pair<long long, long long> s{0, 0};
    std::size_t r = x;
    while (parent[r] != r) {
      s.first += shift[r].first;
      s.second += shift[r].second;
      r = parent[r];
    }
    // Path compression, keeping each node's shift relative to the root.
    std::pair<long long, long long> rest = s;
    for (std::size_t y = x; parent[y] != y;) {
      const std::size_t next = parent[y];
      const auto own = shift[y];
      parent[y] = r;
      shift[y] = rest;
      rest.first -= own.first;
      rest.second -= own.second;
      y = next;
    }
    return {r, s};
  }
  // b's frame origin sits at `b_in_a` in a's frame.
  void join(std::size_t a, std::size_t b, std::pair<long long, long long> b_in_a) {
    const auto [ra, sa] = find(a);
    const auto [rb, sb] = find(b);
    const std::pair<long long, long long> b_in_root{sa.first + b_in_a.first, sa.second + b_in_a.second};
    if (ra == rb) {
      if (b_in_root != sb) spans[ra] = true;  // the same piece met again one cell away
      return;
    }
    parent[rb] = ra;
    shift[rb] = {b_in_root.first - sb.first, b_in_root.second - sb.second};
    spans[ra] = spans[ra] || spans[rb];
  }
};

// Rank 0: the slabs' messages joined into the whole map's clusters, sorted as
// find_clusters sorts them; `cluster_of_piece` the sorted index of every piece.
std::vector<ContactCluster> join_pieces(const std::vector<double>& all, const Grid2D& whole,
                                        const std::vector<std::pair<long, long>>& steps,
                                        std::vector<double>& cluster_of_piece) {
  // Every rank's block, in rank order.
  struct Block {
    long first = 0, rows = 0;
    std::size_t piece0 = 0;  // global index of its first piece
    std::vector<std::array<long long, 4>> edge[2];  // per row (first, last): column, piece (global), ui, uj
  };
  std::vector<Block> blocks;
  std::vector<Piece> pieces;
  for (std::size_t at = 0; at < all.size();) {
    Block b;
    b.first = static_cast<long>(all[at]);
    b.rows = static_cast<long>(all[at + 1]);
    const auto n_pieces = static_cast<std::size_t>(all[at + 2]), n_edge = static_cast<std::size_t>(all[at + 3]);
    at += kHeader;
    b.piece0 = pieces.size();
    for (std::size_t c = 0; c < n_pieces; ++c, at += kPieceValues)
      pieces.push_back({static_cast<long long>(all[at]), static_cast<long long>(all[at + 1]),
                        static_cast<long long>(all[at + 2]), static_cast<long long>(all[at + 3]), all[at + 4] != 0.0});
    for (std::size_t e = 0; e < n_edge; ++e, at += kEdgeValues)
      b.edge[all[at] != 0.0 ? 1 : 0].push_back({static_cast<long long>(all[at + 1]),
                                                 static_cast<long long>(b.piece0) + static_cast<long long>(all[at + 2]),
                                                 static_cast<long long>(all[at + 3]),
                                                 static_cast<long long>(all[at + 4])});
    if (b.rows > 0) blocks.push_back(std::move(b));
  }

  // Join across each slab's last row and the next slab's first row (the last
  // slab's next is the first: the cell's periodic x edge).
  Joined joined(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) joined.spans[k] = pieces[k].spans;
  const long long ny = static_cast<long long>(whole.ny);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Block& lower = blocks[b];
    const Block& upper = blocks[(b + 1) % blocks.size()];
    std::vector<const std::array<long long, 4>*> above(static_cast<std::size_t>(ny), nullptr);
    for (const auto& e : upper.edge[0]) above[static_cast<std::size_t>(e[0])] = &e;
    for (const auto& e : lower.edge[1])
      for (const auto& [di, dj] : steps) {
        if (di != 1) continue;
        const long long j = ((e[0] + dj) % ny + ny) % ny;
        const auto* f = above[static_cast<std::size_t>(j)];
        if (f == nullptr) continue;
        // In the lower piece's frame the upper point sits one row up, dj along.
        const std::pair<long long, long long> upper_in_lower{e[2] + 1 - (*f)[2], e[3] + dj - (*f)[3]};
        joined.join(static_cast<std::size_t>(e[1]), static_cast<std::size_t>((*f)[1]), upper_in_lower);
      }
  }

  // The clusters: their pieces summed in the root's frame, then moved so that
  // the cluster's seed (its first point in raster order) sits at its grid
  // position, as find_clusters' search from that seed places it.
  struct Sum {
    long long seed = -1, points = 0, sum_i = 0, sum_j = 0;
    std::pair<long long, long long> seed_shift{0, 0};
    bool spans = false;
  };
  std::vector<Sum> sums(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const auto [root, s] = joined.find(k);
    Sum& c = sums[root];
    c.points += pieces[k].points;
    c.sum_i += pieces[k].sum_i + pieces[k].points * s.first;
    c.sum_j += pieces[k].sum_j + pieces[k].points * s.second;
    if (c.seed < 0 || pieces[k].seed < c.seed) {
      c.seed = pieces[k].seed;
      c.seed_shift = s;
    }
  }
  std::vector<ContactCluster> clusters;
  std::vector<long long> seeds;
  std::vector<std::size_t> cluster_of_root(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (joined.find(k).first != k) continue;
    cluster_of_root[k] = clusters.size();
    const Sum& c = sums[k];
    ContactCluster out;
    out.points = static_cast<std::size_t>(c.points);
    out.area = static_cast<double>(c.points) * whole.cell_area();
    const double si = static_cast<double>(c.sum_i - c.points * c.seed_shift.first);
    const double sj = static_cast<double>(c.sum_j - c.points * c.seed_shift.second);
    const double cx = si / static_cast<double>(c.points) * whole.dx(), cy = sj / static_cast<double>(c.points) * whole.dy();
    out.centroid_x = cx - std::floor(cx / whole.lx) * whole.lx;
    out.centroid_y = cy - std::floor(cy / whole.ly) * whole.ly;
    out.spans_cell = joined.spans[k];
    clusters.push_back(out);
    seeds.push_back(c.seed);
  }
  // find_clusters meets the clusters in their seeds' raster order, then sorts by size (stable).
  std::vector<std::size_t> order(clusters.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return seeds[a] < seeds[b]; });
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return clusters[a].points > clusters[b].points; });
  std::vector<ContactCluster> sorted;
  sorted.reserve(order.size());
  std::vector<std::size_t> rank_of(order.size());
  for (std::size_t s = 0; s < order.size(); ++s) {
    sorted.push_back(clusters[order[s]]);
    rank_of[order[s]] = s;
  }
  cluster_of_piece.resize(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k)
    cluster_of_piece[k] = static_cast<double>(rank_of[cluster_of_root[joined.find(k).first]]);
  return sorted;
}

}  // namespace

namespace {
// This rank's pieces (label_rows), gathered and joined on rank 0: the whole
// map's clusters there (empty elsewhere), and with `cluster_of_piece` every
// piece's index among them (collective).
std::vector<ContactCluster> gather_and_join(Labelled& mine, const Grid2D& whole,
                                            const std::vector<std::pair<long, long>>& steps,
                                            std::vector<double>& cluster_of_piece) {
  const long long total = mpi::sum(static_cast<long long>(mine.message.size()));
  std::vector<double> all(mpi::is_root() ? static_cast<std::size_t>(total) : 0);
  mpi::gather(mine.message, all);
  mine.message = std::vector<double>();
  return mpi::is_root() ? join_pieces(all, whole, steps, cluster_of_piece) : std::vector<ContactCluster>{};
}

std::vector<std::pair<long, long>> neighbour_steps(Connectivity connectivity) {
  std::vector<std::pair<long, long>> steps = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  if (connectivity == Connectivity::Eight) steps.insert(steps.end(), {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}});
  return steps;
}
}  // namespace

SlabContactMap label_clusters_slab(const RealField& rows, std::size_t first_row, const Grid2D& whole,
                                   Connectivity connectivity) {
  const auto steps = neighbour_steps(connectivity);
  Labelled mine = label_rows(rows, first_row, whole, steps);
  SlabContactMap map;
  std::vector<double> cluster_of_piece;  // rank 0's: every piece's cluster in the sorted order, pieces in rank order
  map.clusters = gather_and_join(mine, whole, steps, cluster_of_piece);
  // Each rank's pieces' clusters, and its points labelled with them.
  std::vector<double> own(mine.pieces);
  mpi::scatter(cluster_of_piece, own);
  map.label.resize(mine.label.size());
  for (std::size_t k = 0; k < mine.label.size(); ++k)
    map.label[k] = mine.label[k] < 0 ? -1 : static_cast<int>(own[static_cast<std::size_t>(mine.label[k])]);
  double count = static_cast<double>(map.clusters.size());
  mpi::broadcast(std::span<double>(&count, 1));
  map.count = static_cast<std::size_t>(count);
  return map;
}

std::vector<ContactCluster> find_clusters_slab(const RealField& rows, std::size_t first_row, const Grid2D& whole,
                                               Connectivity connectivity) {
  const auto steps = neighbour_steps(connectivity);
  Labelled mine = label_rows(rows, first_row, whole, steps);
  mine.label = std::vector<std::int32_t>();  // no labels asked for
  std::vector<double> unused;
  return gather_and_join(mine, whole, steps, unused);
}

}  // namespace wearscale::bem
