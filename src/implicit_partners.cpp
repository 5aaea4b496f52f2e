// ETD-DPD: the implicit scheme's partner atoms and ghost communication (implicit_partners.h).
#include "implicit_partners.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "friction_operator.h"
#include "lammps_compat.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <algorithm>

using namespace LAMMPS_NS;

namespace etd {

void GhostExchange::run(LAMMPS *lmp, Fix *fix, std::initializer_list<Slot> slots, bool positions)
{
  nslots_ = 0;
  for (const Slot &slot : slots) {
    slot.vector->resize(slot.width * (lmp->atom->nlocal + lmp->atom->nghost));
    slots_[nslots_++] = slot;
  }
  positions_ = positions;
  compat::forward_comm(lmp->comm, fix);
  positions_ = false;
}

int GhostExchange::pack(LAMMPS *lmp, int n, const int *list, double *buf, int pbc_flag,
                        const int *pbc) const
{
  Domain *domain = lmp->domain;
  int m = 0;
  // the positions as LAMMPS's own exchange sends them (AtomVec::pack_comm): shifted across a
  // periodic boundary
  double shift[3] = {0.0, 0.0, 0.0};
  if (positions_ && pbc_flag) {
    if (domain->triclinic == 0) {
      shift[0] = pbc[0] * domain->xprd;
      shift[1] = pbc[1] * domain->yprd;
    } else {
      shift[0] = pbc[0] * domain->xprd + pbc[5] * domain->xy + pbc[4] * domain->xz;
      shift[1] = pbc[1] * domain->yprd + pbc[3] * domain->yz;
    }
    shift[2] = pbc[2] * domain->zprd;
  }
  double **x = lmp->atom->x;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    if (positions_)
      for (int k = 0; k < 3; k++) buf[m++] = x[j][k] + shift[k];
    for (int s = 0; s < nslots_; s++) {
      const int width = slots_[s].width;
      const double *values = slots_[s].vector->data() + width * j;
      const bool shifted = slots_[s].image_counts && pbc_flag;
      for (int k = 0; k < width; k++) buf[m++] = values[k] + (shifted ? pbc[k] : 0);
    }
  }
  return m;
}

void GhostExchange::unpack(LAMMPS *lmp, int n, int first, const double *buf) const
{
  double **x = lmp->atom->x;
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (positions_)
      for (int k = 0; k < 3; k++) x[i][k] = buf[m++];
    for (int s = 0; s < nslots_; s++) {
      const int width = slots_[s].width;
      double *values = slots_[s].vector->data() + width * i;
      for (int k = 0; k < width; k++) values[k] = buf[m++];
    }
  }
}

void PartnerMap::find(LAMMPS *lmp, Fix *fix, const PairListView &list, GhostExchange &ghosts)
{
  const int nlocal = lmp->atom->nlocal;
  const int nghost = lmp->atom->nghost;
  const int me = lmp->comm->me;
  // every ghost learns its owner (rank, local index), exact in doubles
  owner_.resize(2 * (nlocal + nghost));
  for (int i = 0; i < nlocal; i++) {
    owner_[2 * i] = me;
    owner_[2 * i + 1] = i;
  }
  // and how many box vectors it lies from its owner (the velocity offset of a moving image)
  image_.assign(6 * (nlocal + nghost), 0.0);
  ghosts.run(lmp, fix, {{&owner_, 2}, {&image_, 6, true}});

  struct Remote {
    int rank, index, ghost;
  };
  std::vector<Remote> remote;
  constexpr int unused = -1, remote_mark = -2;
  // a ghost of an atom of this rank stands for that atom (whether the list uses it or not);
  // the others, images of remote atoms, take slots only where the list uses them
  ghost_partner_.resize(nghost);
  bool any_remote = false;
  for (int g = 0; g < nghost; g++) {
    const bool mine = static_cast<int>(owner_[2 * (nlocal + g)]) == me;
    ghost_partner_[g] = mine ? static_cast<int>(owner_[2 * (nlocal + g) + 1]) : unused;
    any_remote = any_remote || !mine;
  }
  for (int ii = 0; any_remote && ii < list.inum; ii++) {
    const int i = list.ilist[ii];
    const int *jlist = list.firstneigh[i];
    for (int jj = 0; jj < list.numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (j < nlocal || ghost_partner_[j - nlocal] != unused) continue;
      ghost_partner_[j - nlocal] = remote_mark;
      remote.push_back({static_cast<int>(owner_[2 * j]), static_cast<int>(owner_[2 * j + 1]), j});
    }
  }
  // slots grouped by owner; several images of one remote atom share its slot
  std::sort(remote.begin(), remote.end(), [](const Remote &a, const Remote &b) {
    return a.rank != b.rank ? a.rank < b.rank : a.index < b.index;
  });
  std::vector<int> slot_rank, slot_index;
  slot_ghost_.clear();
  for (const Remote &r : remote) {
    if (slot_rank.empty() || r.rank != slot_rank.back() || r.index != slot_index.back()) {
      slot_rank.push_back(r.rank);
      slot_index.push_back(r.index);
      slot_ghost_.push_back(r.ghost);
    }
    ghost_partner_[r.ghost - nlocal] = nlocal + static_cast<int>(slot_rank.size()) - 1;
  }
  exchange_->set_requests(slot_rank, slot_index);
  built_ = lmp->neighbor->ncalls;
}

bool PartnerMap::image_velocity(LAMMPS *lmp, int ghost, double offset[3]) const
{
  if (!(lmp->atom->mask[ghost] & lmp->domain->deform_groupbit)) return false;
  image_velocity_offset(&image_[6 * ghost], lmp->domain->h_rate, offset);
  return offset[0] != 0.0 || offset[1] != 0.0 || offset[2] != 0.0;
}

}    // namespace etd
