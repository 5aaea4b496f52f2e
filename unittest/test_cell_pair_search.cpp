// The implicit scheme's own pair search (solver/cell_pair_search.h) against every pair counted
// by brute force: owned atoms in a periodic box, ghosts as LAMMPS makes them (the images within
// a shell), both newton settings; and a far-away atom, which must not blow up the cell grid.
#include "cell_pair_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <thread>
#include <utility>
#include <vector>

namespace {

struct Atoms {
  int nlocal = 0;
  std::vector<double> x;     // owned atoms, then ghosts
  std::vector<int> owner;    // per atom: the owned atom it is an image of
  int count() const { return static_cast<int>(owner.size()); }
};

// n atoms in a periodic cube of side L; ghosts: every image within 'shell' of the box
Atoms periodic_box(int n, double L, double shell, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, L);
  Atoms a;
  a.nlocal = n;
  for (int i = 0; i < n; i++) {
    for (int k = 0; k < 3; k++) a.x.push_back(u(rng));
    a.owner.push_back(i);
  }
  for (int i = 0; i < n; i++)
    for (int sx = -1; sx <= 1; sx++)
      for (int sy = -1; sy <= 1; sy++)
        for (int sz = -1; sz <= 1; sz++) {
          if (sx == 0 && sy == 0 && sz == 0) continue;
          const int s[3] = {sx, sy, sz};
          double p[3];
          bool inside = true;
          for (int k = 0; k < 3; k++) {
            p[k] = a.x[3 * i + k] + s[k] * L;
            inside = inside && p[k] > -shell && p[k] < L + shell;
          }
          if (!inside) continue;
          for (int k = 0; k < 3; k++) a.x.push_back(p[k]);
          a.owner.push_back(i);
        }
  return a;
}

using Pairs = std::multiset<std::pair<int, int>>;

Pairs listed(const etd::PairListView &view)
{
  Pairs pairs;
  for (int ii = 0; ii < view.inum; ii++) {
    const int i = view.ilist[ii];
    for (int jj = 0; jj < view.numneigh[i]; jj++) pairs.insert({i, view.firstneigh[i][jj]});
  }
  return pairs;
}

double distance_squared(const Atoms &a, int i, int j)
{
  double rsq = 0.0;
  for (int k = 0; k < 3; k++) rsq += std::pow(a.x[3 * i + k] - a.x[3 * j + k], 2);
  return rsq;
}

// newton off: every owned-owned pair once from its lower index, every owned-ghost pair from
// the owned atom
TEST(CellPairSearch, NewtonOffListsEveryOwnedAndGhostPair)
{
  for (double cutoff : {1.0, 1.37}) {
    const Atoms a = periodic_box(600, 6.0, 1.5, 7);
    etd::CellPairSearch search;
    search.build(a.x.data(), a.nlocal, a.count(), cutoff, true);
    Pairs expected;
    for (int i = 0; i < a.nlocal; i++)
      for (int j = i + 1; j < a.count(); j++)
        if (distance_squared(a, i, j) < cutoff * cutoff) expected.insert({i, j});
    ASSERT_GT(expected.size(), 1000u);
    EXPECT_EQ(listed(search.view()), expected) << "cutoff " << cutoff;
    EXPECT_EQ(search.pairs(), expected.size());
  }
}

// newton on: each physical pair of the periodic system exactly once, whichever image holds it
TEST(CellPairSearch, NewtonOnListsEachPeriodicPairOnce)
{
  const double L = 6.0, cutoff = 1.0;
  const Atoms a = periodic_box(600, L, 1.3, 11);
  etd::CellPairSearch search;
  search.build(a.x.data(), a.nlocal, a.count(), cutoff, false);
  std::set<std::pair<int, int>> expected;    // by the minimum image, (lower, higher) owner
  for (int i = 0; i < a.nlocal; i++)
    for (int j = i + 1; j < a.nlocal; j++) {
      double rsq = 0.0;
      for (int k = 0; k < 3; k++) {
        double d = a.x[3 * i + k] - a.x[3 * j + k];
        d -= L * std::round(d / L);
        rsq += d * d;
      }
      if (rsq < cutoff * cutoff) expected.insert({i, j});
    }
  Pairs found;
  for (const auto &p : listed(search.view())) {
    EXPECT_LT(p.first, a.nlocal);
    const int u = a.owner[p.first], w = a.owner[p.second];
    found.insert({std::min(u, w), std::max(u, w)});
  }
  ASSERT_GT(expected.size(), 1000u);
  EXPECT_EQ(found.size(), expected.size());    // none twice
  const std::set<std::pair<int, int>> distinct(found.begin(), found.end());
  EXPECT_EQ(distinct, expected);
}

// one atom far outside the others (lost, or a wall far away): the grid coarsens instead of
// allocating cells for the empty space, and every pair is still found
TEST(CellPairSearch, FarAtomKeepsTheGridSmall)
{
  Atoms a = periodic_box(300, 5.0, 0.0, 3);
  for (double c : {1e6, 2e6, -1e6}) a.x.push_back(c);
  a.owner.push_back(300);
  etd::CellPairSearch search;
  search.build(a.x.data(), a.nlocal, a.count(), 1.0, true);
  size_t expected = 0;
  for (int i = 0; i < a.nlocal; i++)
    for (int j = i + 1; j < a.count(); j++) expected += distance_squared(a, i, j) < 1.0;
  EXPECT_EQ(search.pairs(), expected);
  EXPECT_LT(search.memory_usage(), 1000000u);
}

// the rows of a list, in their order
std::vector<std::vector<int>> rows(const etd::PairListView &view)
{
  std::vector<std::vector<int>> out;
  for (int ii = 0; ii < view.inum; ii++) {
    const int i = view.ilist[ii];
    out.emplace_back(view.firstneigh[i], view.firstneigh[i] + view.numneigh[i]);
  }
  return out;
}

// slabs searched by a runner (threads, or one after another backwards) give the serial search's
// list entry for entry, with both newton settings; and a runner's search repeated on a second
// configuration leaves nothing of the first
TEST(CellPairSearch, SlabsGiveTheSerialListEntryForEntry)
{
  const etd::CellPairSearch::ChunkRunner backwards = [](int n, const std::function<void(int)> &body) {
    for (int k = n - 1; k >= 0; k--) body(k);
  };
  const etd::CellPairSearch::ChunkRunner threads = [](int n, const std::function<void(int)> &body) {
    std::vector<std::thread> pool;
    for (int k = 0; k < n; k++) pool.emplace_back(body, k);
    for (std::thread &t : pool) t.join();
  };
  for (bool newton_off : {true, false}) {
    for (unsigned seed : {5u, 6u}) {
      const Atoms a = periodic_box(900, 7.0, 1.3, seed);
      etd::CellPairSearch serial;
      serial.build(a.x.data(), a.nlocal, a.count(), 1.1, newton_off);
      const auto expected = rows(serial.view());
      ASSERT_GT(serial.pairs(), 1000u);
      static etd::CellPairSearch reused;    // (kept across configurations)
      for (int chunks : {2, 3, 7, 100}) {
        for (const auto *runner : {&backwards, &threads}) {
          reused.build(a.x.data(), a.nlocal, a.count(), 1.1, newton_off, chunks, *runner);
          EXPECT_EQ(rows(reused.view()), expected) << chunks << " chunks, newton_off " << newton_off;
          EXPECT_EQ(reused.pairs(), serial.pairs());
        }
      }
    }
  }
}

TEST(CellPairSearch, NoOwnedAtoms)
{
  const double ghost[3] = {0.0, 0.0, 0.0};
  etd::CellPairSearch search;
  search.build(ghost, 0, 1, 1.0, false);
  EXPECT_EQ(search.view().inum, 0);
  EXPECT_EQ(search.pairs(), 0u);
}

}    // namespace
