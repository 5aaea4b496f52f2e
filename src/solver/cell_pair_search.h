// ETD-DPD: the implicit scheme's own pair search. At the steps this scheme takes, the fastest
// atoms cross half of LAMMPS's skin in one step, so LAMMPS rebuilds its lists at every step
// anyway; one search per step over a grid of cells, at the positions of the moment and with a
// small margin for the coming half drift, costs less than that build. Pure C++ (unit-tested
// without LAMMPS); the result reads like a LAMMPS half list.
#ifndef ETD_CELL_PAIR_SEARCH_H
#define ETD_CELL_PAIR_SEARCH_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace etd {

// The fields of a LAMMPS half neighbor list that the package's loops read: for ii < inum,
// atom i = ilist[ii] has numneigh[i] partners at firstneigh[i].
struct PairListView {
  int inum = 0;
  const int *ilist = nullptr;
  const int *numneigh = nullptr;
  int *const *firstneigh = nullptr;
};

// The view of any list with those fields (LAMMPS's NeighList)
template <typename List> inline PairListView view_of(const List &list)
{
  return {list.inum, list.ilist, list.numneigh, list.firstneigh};
}

// Runs body(k) for every k in [0, n), in any order, possibly at the same time (threads)
using ChunkRunner = std::function<void(int n, const std::function<void(int)> &body)>;

// Loops over [0, n) in up to `chunks` ranges run at once by `runner` (host threads); one range,
// run in place, without a runner or where n is small. A reduction that adds each range's part
// in range order sums as a plain loop does when there is one range.
struct ParallelRanges {
  int chunks = 1;
  ChunkRunner runner;
  // how many ranges for_ranges() splits n into
  int ranges(int n) const { return (runner && chunks > 1 && n >= 2 * chunks) ? chunks : 1; }
  // body(begin, end, range) for the ranges(n) ranges of [0, n)
  template <class Body> void for_ranges(int n, Body &&body) const
  {
    const int count = ranges(n);
    if (count == 1) {
      body(0, n, 0);
      return;
    }
    runner(count, [&](int c) {
      body(static_cast<int>(static_cast<long>(c) * n / count),
           static_cast<int>(static_cast<long>(c + 1) * n / count), c);
    });
  }
};

class CellPairSearch {
 public:
  using ChunkRunner = etd::ChunkRunner;

  // Every pair (i, j) with i < nlocal, j < nall and |x_i - x_j| < cutoff (x: nall rows of 3):
  //  - two owned atoms, once, listed from the lower index;
  //  - an owned atom and a ghost, listed from the owned atom: with newton_off always (the
  //    ghost's owner lists the pair too), otherwise once per pair of periodic images, where the
  //    ghost lies "above" (larger z, then y, then x): the images i - j' and j - i' of one pair
  //    are displaced oppositely, so exactly one of them is kept.
  // With a runner, up to `chunks` slabs of cells are searched by it at once; the list is the
  // same, entry for entry, whatever the chunks and however the runner orders them.
  void build(const double *x, int nlocal, int nall, double cutoff, bool newton_off,
             int chunks = 1, const ChunkRunner &runner = nullptr)
  {
    nlocal_ = nlocal;
    nchunks_ = 0;
    if (nlocal > 0) {
      bin(x, nall, cutoff, chunks, runner);
      nchunks_ = std::max(1, std::min(runner ? chunks : 1, n_[2]));
      if (static_cast<int>(chunks_.size()) < nchunks_) chunks_.resize(nchunks_);
      const double cutsq = cutoff * cutoff;
      for_each_chunk(runner, [this, cutsq, newton_off](int k) {
        collect(chunks_[k], k * n_[2] / nchunks_, (k + 1) * n_[2] / nchunks_, cutsq, newton_off);
      });
    }
    index(nlocal, runner);
  }

  PairListView view() const
  {
    return {nlocal_, ilist_.data(), numneigh_.data(), firstneigh_.data()};
  }
  std::size_t pairs() const { return neighbors_.size(); }
  std::size_t memory_usage() const
  {
    std::size_t found = 0;
    for (const Found &chunk : chunks_)
      found += chunk.first.capacity() + chunk.second.capacity() + chunk.rows.capacity();
    return sizeof(int) *
        (ilist_.capacity() + numneigh_.capacity() + neighbors_.capacity() + start_.capacity() +
         owned_before_.capacity() + sorted_.capacity() + cell_of_.capacity() + fill_.capacity() +
         found) +
        sizeof(int *) * firstneigh_.capacity() +
        sizeof(double) * (sorted_x_.capacity() + bounds_.capacity());
  }

 private:
  static bool above(double dx, double dy, double dz)
  {
    if (dz != 0.0) return dz > 0.0;
    if (dy != 0.0) return dy > 0.0;
    return dx > 0.0;
  }

  // Cells no smaller than the cutoff over the atoms' bounding box, so that a pair lies in one
  // cell or two neighbouring ones; atoms and their positions sorted by cell (sort_by_cell()).
  void bin(const double *x, int nall, double cutoff, int chunks, const ChunkRunner &runner)
  {
    const ParallelRanges split{std::min(chunks, max_bin_ranges), runner};
    double lo[3], hi[3], inverse[3];
    bounding_box(x, nall, split, lo, hi);
    make_cells(lo, hi, cutoff, nall, inverse);
    sort_by_cell(x, nall, split, lo, inverse);
    // the owned atoms in the cells before each (owned atoms come first in a cell: index order)
    const int ncells = n_[0] * n_[1] * n_[2];
    owned_before_.resize(ncells + 1);
    owned_before_[0] = 0;
    for (int c = 0; c < ncells; c++) {
      int owned = start_[c];
      while (owned < start_[c + 1] && sorted_[owned] < nlocal_) owned++;
      owned_before_[c + 1] = owned_before_[c] + (owned - start_[c]);
    }
  }

  // the atoms' bounding box, each range's first and then theirs combined
  void bounding_box(const double *x, int nall, const ParallelRanges &split, double lo[3],
                    double hi[3])
  {
    const int ranges = split.ranges(nall);
    std::vector<double> &bounds = bounds_;    // per range: lo[3], hi[3]
    bounds.assign(6 * ranges, 0.0);
    split.for_ranges(nall, [&](int first, int last, int r) {
      double *range_lo = &bounds[6 * r], *range_hi = range_lo + 3;
      for (int k = 0; k < 3; k++) range_lo[k] = range_hi[k] = x[3 * first + k];
      for (int j = first + 1; j < last; j++)
        for (int k = 0; k < 3; k++) {
          range_lo[k] = std::min(range_lo[k], x[3 * j + k]);
          range_hi[k] = std::max(range_hi[k], x[3 * j + k]);
        }
    });
    for (int k = 0; k < 3; k++) {
      lo[k] = bounds[k];
      hi[k] = bounds[3 + k];
      for (int r = 1; r < ranges; r++) {
        lo[k] = std::min(lo[k], bounds[6 * r + k]);
        hi[k] = std::max(hi[k], bounds[6 * r + 3 + k]);
      }
    }
  }

  // n_ cells along each axis, no smaller than the cutoff, and inverse: cells per unit length. A
  // box stretched by a far-away atom gets coarser cells rather than more cells than atoms.
  void make_cells(const double lo[3], const double hi[3], double cutoff, int nall,
                  double inverse[3])
  {
    double size = cutoff > 0.0 ? cutoff : 1.0;
    const double cell_budget = 2.0 * nall + 27.0;
    for (;;) {
      double cells = 1.0;
      for (int k = 0; k < 3; k++) cells *= std::max(1.0, std::floor((hi[k] - lo[k]) / size));
      if (cells <= cell_budget) break;
      size *= 1.26;
    }
    for (int k = 0; k < 3; k++) {
      n_[k] = std::max(1, static_cast<int>(std::floor((hi[k] - lo[k]) / size)));
      inverse[k] = hi[k] > lo[k] ? n_[k] / (hi[k] - lo[k]) : 0.0;
    }
  }

  // The atoms and their positions sorted by cell: a counting sort in ranges of atoms at once
  // (with a runner), each range counting its atoms per cell and placing them after the lower
  // ranges' atoms of the same cell, so that every cell lists its atoms in index order whatever
  // the ranges
  void sort_by_cell(const double *x, int nall, const ParallelRanges &split, const double lo[3],
                    const double inverse[3])
  {
    const int ranges = split.ranges(nall);
    const int ncells = n_[0] * n_[1] * n_[2];
    cell_of_.resize(nall);
    // per range and cell: its atoms there, then where the first of them goes
    fill_.assign(static_cast<std::size_t>(ranges) * ncells, 0);
    split.for_ranges(nall, [&](int first, int last, int r) {
      int *count = &fill_[static_cast<std::size_t>(r) * ncells];
      for (int j = first; j < last; j++) {
        int c[3];
        for (int k = 0; k < 3; k++)
          c[k] = std::min(n_[k] - 1, static_cast<int>((x[3 * j + k] - lo[k]) * inverse[k]));
        const int cell = c[0] + n_[0] * (c[1] + n_[1] * c[2]);
        cell_of_[j] = cell;
        count[cell]++;
      }
    });
    start_.resize(ncells + 1);
    int placed = 0;
    for (int c = 0; c < ncells; c++) {
      start_[c] = placed;
      for (int r = 0; r < ranges; r++) {
        int &slot = fill_[static_cast<std::size_t>(r) * ncells + c];
        const int count = slot;
        slot = placed;
        placed += count;
      }
    }
    start_[ncells] = placed;
    sorted_.resize(nall);
    sorted_x_.resize(3 * static_cast<std::size_t>(nall));
    split.for_ranges(nall, [&](int first, int last, int r) {
      int *slot = &fill_[static_cast<std::size_t>(r) * ncells];
      for (int j = first; j < last; j++) {
        const int s = slot[cell_of_[j]]++;
        sorted_[s] = j;
        for (int k = 0; k < 3; k++) sorted_x_[3 * s + k] = x[3 * j + k];
      }
    });
  }

  // The pairs one slab of cells found: `found` of them, as atom indices, oriented (both
  // written ahead of the count), and per owned atom its count of them, then (index()) where the
  // slab's entries of its row go
  struct Found {
    std::vector<int> first, second, rows;
    std::size_t found = 0;
  };

  // body(k) for each of this search's slabs: by the runner where there are several
  template <class Body> void for_each_chunk(const ChunkRunner &runner, Body body)
  {
    if (nchunks_ == 1)
      body(0);
    else if (nchunks_ > 1)
      runner(nchunks_, body);
  }

  // Every pair within the cutoff with at least one owned atom, once: each atom of a cell of the
  // slab [z0, z1) against the atoms after it in its own cell and the next one along x, and
  // against four rows of three cells ahead of it (y + 1 in its plane; y - 1, y, y + 1 in the
  // next plane). Cells along x are contiguous in the sorted order, so an atom's candidates are
  // five ranges rather than fourteen cells of a few atoms each. A ghost's ranges without owned
  // atoms are skipped. (Cells of half the cutoff, with their larger stencil, cost twice as much
  // here: measured at 3,000 atoms.) Each atom's pairs are then oriented and kept or not
  // (orient()) while they are in cache.
  void collect(Found &out, int z0, int z1, double cutsq, bool newton_off) const
  {
    const int nx = n_[0], ny = n_[1], nz = n_[2];
    out.found = 0;
    out.rows.assign(nlocal_, 0);
    for (int cz = z0; cz < z1; cz++)
      for (int cy = 0; cy < ny; cy++)
        for (int cx = 0; cx < nx; cx++) {
          const int c = cx + nx * (cy + ny * cz);
          const int a0 = start_[c], a1 = start_[c + 1];
          if (a0 == a1) continue;
          // the rows ahead: [first, last) in sorted_, and whether they hold an owned atom
          const int xlo = std::max(cx - 1, 0), xhi = std::min(cx + 1, nx - 1);
          Range rows[4];
          int nrows = 0;
          const int ahead[4][2] = {{cy + 1, cz}, {cy - 1, cz + 1}, {cy, cz + 1}, {cy + 1, cz + 1}};
          for (const auto &yz : ahead) {
            if (yz[0] < 0 || yz[0] >= ny || yz[1] >= nz) continue;
            const int base = nx * (yz[0] + ny * yz[1]);
            const Range r{start_[base + xlo], start_[base + xhi + 1],
                          owned_before_[base + xhi + 1] > owned_before_[base + xlo]};
            if (r.last > r.first) rows[nrows++] = r;
          }
          // this cell and the next along x
          const int along = cx + 1 < nx ? c + 2 : c + 1;
          const bool along_owned = owned_before_[along] > owned_before_[c];
          const int along_last = start_[along];
          for (int a = a0; a < a1; a++) {
            const bool a_owned = sorted_[a] < nlocal_;
            std::size_t candidates = along_last - a - 1;
            for (int r = 0; r < nrows; r++) candidates += rows[r].last - rows[r].first;
            if (out.found + candidates > out.second.size()) {
              out.second.resize(2 * (out.found + candidates));
              out.first.resize(out.second.size());
            }
            const std::size_t begin = out.found;
            if (a_owned) {
              scan<true>(out, a, a + 1, along_last, cutsq);
              for (int r = 0; r < nrows; r++) scan<true>(out, a, rows[r].first, rows[r].last, cutsq);
            } else {
              if (along_owned) scan<false>(out, a, a + 1, along_last, cutsq);
              for (int r = 0; r < nrows; r++)
                if (rows[r].owned) scan<false>(out, a, rows[r].first, rows[r].last, cutsq);
            }
            orient(out, a, begin, newton_off);
          }
        }
  }

  // The pairs of atom a (sorted position) from out's entry begin on, as atom indices: oriented
  // (owned atom first, the lower index of two owned ones) and kept or not by the newton
  // setting, each counted in its first atom's row
  void orient(Found &out, int a, std::size_t begin, bool newton_off) const
  {
    const double *xs = sorted_x_.data();
    const int atom_a = sorted_[a];
    std::size_t kept = begin;
    for (std::size_t p = begin; p < out.found; p++) {
      int sa = a, sb = out.second[p];
      int i = atom_a, j = sorted_[sb];
      if (i >= nlocal_ || (j < nlocal_ && j < i)) {
        std::swap(i, j);
        std::swap(sa, sb);
      }
      if (j >= nlocal_ && !newton_off &&
          !above(xs[3 * sb] - xs[3 * sa], xs[3 * sb + 1] - xs[3 * sa + 1],
                 xs[3 * sb + 2] - xs[3 * sa + 2]))
        continue;
      out.first[kept] = i;
      out.second[kept] = j;
      kept++;
      out.rows[i]++;
    }
    out.found = kept;
  }

  struct Range {
    int first, last;
    bool owned;    // holds an owned atom
  };

  // The candidates [first, last) of atom a (positions in sorted_) within the cutoff, appended
  // to out.second; an owned a pairs with any, a ghost with owned atoms only. Every candidate is
  // written and the count advanced only for pairs kept: about one candidate in six is kept, a
  // branch the processor would mostly mispredict.
  template <bool A_OWNED>
  void scan(Found &out, int a, int first, int last, double cutsq) const
  {
    int *second = out.second.data() + out.found;
    const double *xs = sorted_x_.data();
    const double xa = xs[3 * a], ya = xs[3 * a + 1], za = xs[3 * a + 2];
    int kept = 0;
    for (int b = first; b < last; b++) {
      const double dx = xs[3 * b] - xa, dy = xs[3 * b + 1] - ya, dz = xs[3 * b + 2] - za;
      second[kept] = b;
      const bool close = dx * dx + dy * dy + dz * dz < cutsq;
      kept += (A_OWNED ? close : close && sorted_[b] < nlocal_) ? 1 : 0;
    }
    out.found += kept;
  }

  // The slabs' pairs sorted by their first atoms into the list's rows: each row holds the first
  // slab's entries, then the next slab's, each in the order found (the order one slab of all
  // cells gives).
  void index(int nlocal, const ChunkRunner &runner)
  {
    ilist_.resize(nlocal);
    for (int i = 0; i < nlocal; i++) ilist_[i] = i;
    // where each row starts, and each slab's part of it
    numneigh_.assign(nlocal, 0);
    std::size_t offset = 0;
    for (int i = 0; i < nlocal; i++) {
      const std::size_t row = offset;
      for (int k = 0; k < nchunks_; k++) {
        const int count = chunks_[k].rows[i];
        chunks_[k].rows[i] = static_cast<int>(offset);
        offset += count;
      }
      numneigh_[i] = static_cast<int>(offset - row);
    }
    neighbors_.resize(offset);
    firstneigh_.resize(nlocal);
    offset = 0;
    for (int i = 0; i < nlocal; i++) {
      firstneigh_[i] = neighbors_.data() + offset;
      offset += numneigh_[i];
    }
    for_each_chunk(runner, [&](int k) {
      Found &chunk = chunks_[k];
      for (std::size_t p = 0; p < chunk.found; p++)
        neighbors_[chunk.rows[chunk.first[p]]++] = chunk.second[p];
    });
  }

  int nlocal_ = 0;
  int n_[3] = {1, 1, 1};
  // owned_before_: per cell, the owned atoms in the cells before it
  std::vector<int> cell_of_, start_, owned_before_, sorted_, fill_;
  std::vector<double> bounds_;
  static constexpr int max_bin_ranges = 16;    // (each range counts over all cells)
  std::vector<double> sorted_x_;
  std::vector<Found> chunks_;    // the pairs each slab found; nchunks_ of them this search
  int nchunks_ = 0;
  std::vector<int> ilist_, numneigh_, neighbors_;
  std::vector<int *> firstneigh_;
};

}    // namespace etd

#endif
