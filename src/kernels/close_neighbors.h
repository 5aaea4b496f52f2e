// ETD-DPD: one atom's neighbours within the cutoff, gathered before the pair loop proper.
//
// With LAMMPS's default skin of 0.3 about half of a DPD neighbour list lies beyond the cutoff.
// Testing each neighbour in the pair loop costs a mispredicted branch for about every other
// one; gathering those within the cutoff first, with the count advanced by the test's result
// and no branch, and then doing the work on them alone made dpd/gen's force loop a third
// cheaper (bench/README.md). Used by the pair loop (PairDPDBase::eval) and the implicit
// scheme's pair build.
#ifndef ETD_CLOSE_NEIGHBORS_H
#define ETD_CLOSE_NEIGHBORS_H

#include <vector>

namespace etd {

// Copies the entries of jlist (special bits kept) whose atom j lies within the cutoff of atom i
// at (xi0, xi1, xi2) into close, returns how many. x: LAMMPS's contiguous positions (row j at
// 3 j); neighbor_mask: LAMMPS's NEIGHMASK; within(j, rsq): whether the pair interacts.
template <typename Within>
inline int gather_close_neighbors(const int *jlist, int jnum, int neighbor_mask, const double *x,
                                  double xi0, double xi1, double xi2, Within within,
                                  std::vector<int> &close)
{
  if (static_cast<int>(close.size()) < jnum) close.resize(jnum);
  int *out = close.data();
  int count = 0;
  for (int jj = 0; jj < jnum; jj++) {
    const int j = jlist[jj] & neighbor_mask;
    const double *xj = x + 3 * j;
    const double dx = xi0 - xj[0], dy = xi1 - xj[1], dz = xi2 - xj[2];
    out[count] = jlist[jj];
    count += within(j, dx * dx + dy * dy + dz * dz) ? 1 : 0;
  }
  return count;
}

}    // namespace etd

#endif
