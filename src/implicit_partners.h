// ETD-DPD: which atoms the implicit scheme's friction operator acts on, and the ghost
// communication that finds them.
//
// The "partners" are the owned atoms [0, nlocal), then one slot for each atom of another rank
// that a pair uses (solver/partner_exchange.h). Images of owned atoms are the owned atoms
// themselves, and a pair that crosses ranks is held by both, each updating its own atom, so
// applying G needs one exchange of the slots' values and no reverse sum.
#ifndef ETD_IMPLICIT_PARTNERS_H
#define ETD_IMPLICIT_PARTNERS_H

#include "cell_pair_search.h"
#include "lammps.h"
#include "lmptype.h"
#include "partner_exchange.h"

#include <initializer_list>
#include <memory>
#include <vector>

namespace LAMMPS_NS {
class Fix;
}    // namespace LAMMPS_NS

namespace etd {

// One LAMMPS forward (ghost) communication carrying several per-atom vectors at once, and
// optionally the positions with their periodic shift (every exchange is a point where the
// ranks wait for each other). The fix's pack/unpack_forward_comm hand over to pack/unpack.
class GhostExchange {
 public:
  struct Slot {
    std::vector<double> *vector;
    int width;                    // values per atom
    bool image_counts = false;    // 6 values per atom that gain the periodic shift (pbc) sent
  };
  // Resizes each vector to the owned and ghost atoms and fills the ghosts' values from their
  // owners (and the ghosts' positions, with positions).
  void run(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *fix, std::initializer_list<Slot> slots,
           bool positions = false);
  int pack(LAMMPS_NS::LAMMPS *lmp, int n, const int *list, double *buf, int pbc_flag,
           const int *pbc) const;
  void unpack(LAMMPS_NS::LAMMPS *lmp, int n, int first, const double *buf) const;
  static constexpr int max_width = 9;    // positions and the widest slot set the fix uses

 private:
  static constexpr int max_slots = 3;
  Slot slots_[max_slots];
  int nslots_ = 0;
  bool positions_ = false;
};

class PartnerMap {
 public:
  explicit PartnerMap(MPI_Comm world) : exchange_(new PartnerExchange(world)) {}
  // Which partner each ghost stands for: every image of an atom of this rank, and the images of
  // remote atoms that the list uses (slots); once per list (ghosts are renumbered
  // only at LAMMPS's reneighboring, but the scheme's own search lists other ghosts each step);
  // collective.
  void find(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *fix, const PairListView &list,
            GhostExchange &ghosts);
  bool current(LAMMPS_NS::bigint neighbor_calls) const { return built_ == neighbor_calls; }
  void invalidate() { built_ = -1; }
  int count(int nlocal) const { return nlocal + slots(); }    // owned atoms and slots
  int slots() const { return static_cast<int>(slot_ghost_.size()); }
  int of_ghost(int ghost, int nlocal) const { return ghost_partner_[ghost - nlocal]; }
  int ghost_of_slot(int slot) const { return slot_ghost_[slot]; }    // one image of it
  const std::vector<int> &ghost_partners() const { return ghost_partner_; }    // of_ghost's table
  // the velocity a periodic image has on top of its owner's under fix deform ... remap v, as
  // LAMMPS's own ghost communication adds it (AtomVec::pack_comm_vel); false where it has none
  bool image_velocity(LAMMPS_NS::LAMMPS *lmp, int ghost, double offset[3]) const;
  // per atom (owned, then ghosts), 6 values: its count of each box vector from its owner
  const std::vector<double> &image_counts() const { return image_; }
  // fills the slots of a per-partner vector (width values each) from their owners
  void exchange(double *values, int nlocal, int width)
  {
    exchange_->exchange(values, nlocal, width);
  }
  // the same with the values packed by the caller (PartnerExchange::swap)
  const std::vector<int> &sent() const { return exchange_->sent(); }
  void swap(const double *sent_values, double *slot_values, int width)
  {
    exchange_->swap(sent_values, slot_values, width);
  }
  size_t memory_usage() const
  {
    return sizeof(int) * (ghost_partner_.capacity() + slot_ghost_.capacity()) +
        sizeof(double) * (owner_.capacity() + image_.capacity());
  }

 private:
  std::unique_ptr<PartnerExchange> exchange_;
  LAMMPS_NS::bigint built_ = -1;      // neighbor->ncalls of the list they were found from
  std::vector<int> ghost_partner_;    // per ghost (index - nlocal): its partner index, or -1
                                      // (a remote atom's image the list does not use)
  std::vector<int> slot_ghost_;       // per slot: one ghost that is an image of it
  std::vector<double> owner_;         // per atom: owner rank and index
  std::vector<double> image_;         // per atom: its count of box vectors (pbc) from its owner
};

}    // namespace etd

#endif
