// ETD-DPD: per-atom values of the atoms that other ranks own and this rank's pairs need.
//
// The implicit scheme applies its friction operator some 10-30 times a step, and each time the
// pairs that cross a subdomain boundary need their partner's current value. LAMMPS's own ghost
// communication moves every ghost atom (out to the neighbor cutoff plus skin, periodic images
// of one's own atoms included), and a newton-on sum needs a reverse pass as well. Here each
// rank receives exactly the remote atoms its pairs use, once each however many images of them
// it holds, in one message per partner rank, and nothing goes back: the fix holds every pair
// that crosses ranks on both sides, each side updating only its own atom.
//
// A rank lists what it needs as "slots", (owner rank, owner's local index), grouped by owner;
// set_requests() tells every owner what to send (collective over the communicator), and
// exchange() then fills the slots of a per-atom vector from the owners' values. swap() is the
// same exchange for a caller that packs the values sent and unpacks the slots itself (the
// Kokkos solve, whose vectors may live in a GPU's memory: only these cross to the host).
#ifndef ETD_PARTNER_EXCHANGE_H
#define ETD_PARTNER_EXCHANGE_H

#include <mpi.h>

#include <stdexcept>
#include <vector>

namespace etd {

class PartnerExchange {
 public:
  explicit PartnerExchange(MPI_Comm world)
  {
    // a private communicator: the requests are received from any source, and must not meet
    // any other message of the program
    MPI_Comm_dup(world, &comm_);
    MPI_Comm_rank(comm_, &me_);
    MPI_Comm_size(comm_, &nprocs_);
  }
  ~PartnerExchange() { MPI_Comm_free(&comm_); }
  PartnerExchange(const PartnerExchange &) = delete;
  PartnerExchange &operator=(const PartnerExchange &) = delete;

  // Slot s of this rank is owner_index[s] on rank owner_rank[s] (never this rank); the slots
  // of one owner must be consecutive. Collective: every rank of the communicator calls it.
  void set_requests(const std::vector<int> &owner_rank, const std::vector<int> &owner_index)
  {
    sources_.clear();
    for (size_t s = 0; s < owner_rank.size(); s++) {
      if (owner_rank[s] == me_ || owner_rank[s] < 0 || owner_rank[s] >= nprocs_)
        throw std::invalid_argument("PartnerExchange: a slot's owner must be another rank");
      if (sources_.empty() || sources_.back().rank != owner_rank[s]) {
        for (const Partner &earlier : sources_)
          if (earlier.rank == owner_rank[s])
            throw std::invalid_argument(
                "PartnerExchange: the slots of one owner must be consecutive");
        sources_.push_back({owner_rank[s], static_cast<int>(s), 0});
      }
      sources_.back().count++;
    }
    slots_ = static_cast<int>(owner_rank.size());
    targets_.clear();
    sent_.clear();
    if (nprocs_ == 1) return;

    // how many ranks will ask this one (each rank flags the owners it asks)
    std::vector<int> asks(nprocs_, 0);
    for (const Partner &p : sources_) asks[p.rank] = 1;
    int askers = 0;
    MPI_Reduce_scatter_block(asks.data(), &askers, 1, MPI_INT, MPI_SUM, comm_);

    std::vector<MPI_Request> asked(sources_.size());
    for (size_t k = 0; k < sources_.size(); k++)
      MPI_Isend(owner_index.data() + sources_[k].first, sources_[k].count, MPI_INT,
                sources_[k].rank, request_tag, comm_, &asked[k]);
    targets_.resize(askers);
    for (Partner &t : targets_) {
      MPI_Status status;
      MPI_Probe(MPI_ANY_SOURCE, request_tag, comm_, &status);
      MPI_Get_count(&status, MPI_INT, &t.count);
      t.rank = status.MPI_SOURCE;
      t.first = static_cast<int>(sent_.size());
      sent_.resize(sent_.size() + t.count);
      MPI_Recv(sent_.data() + t.first, t.count, MPI_INT, t.rank, request_tag, comm_,
               MPI_STATUS_IGNORE);
    }
    MPI_Waitall(static_cast<int>(asked.size()), asked.data(), MPI_STATUSES_IGNORE);
  }

  // values[width * (offset + s) + k] = the owner's values[width * index + k] for every slot s
  // (values must hold offset + slots() atoms). Collective among the partners.
  void exchange(double *values, int offset, int width)
  {
    if (idle()) return;
    send_buffer_.resize(static_cast<size_t>(width) * sent_.size());
    double *buffer = send_buffer_.data();
    for (int index : sent_)
      for (int k = 0; k < width; k++) *buffer++ = values[static_cast<size_t>(width) * index + k];
    swap(send_buffer_.data(), values + static_cast<size_t>(width) * offset, width);
  }

  // The exchange with the values packed by the caller: sent_values holds width values for each
  // atom of sent(), in that order; slot_values receives width values for each slot. Collective
  // among the partners.
  void swap(const double *sent_values, double *slot_values, int width)
  {
    if (idle()) return;
    requests_.resize(sources_.size() + targets_.size());
    size_t n = 0;
    for (const Partner &p : sources_)
      MPI_Irecv(slot_values + static_cast<size_t>(width) * p.first, width * p.count, MPI_DOUBLE,
                p.rank, values_tag, comm_, &requests_[n++]);
    for (const Partner &t : targets_)
      MPI_Isend(sent_values + static_cast<size_t>(width) * t.first, width * t.count, MPI_DOUBLE,
                t.rank, values_tag, comm_, &requests_[n++]);
    MPI_Waitall(static_cast<int>(n), requests_.data(), MPI_STATUSES_IGNORE);
  }

  // this rank neither sends nor receives (one rank; a subdomain whose pairs stay inside it)
  bool idle() const { return sources_.empty() && targets_.empty(); }
  int slots() const { return slots_; }
  // the owned atoms this rank sends in one exchange, in the order swap() takes their values
  const std::vector<int> &sent() const { return sent_; }

 private:
  static constexpr int request_tag = 1, values_tag = 2;
  struct Partner {
    int rank;
    int first;    // sources: its first slot; targets: its first entry of sent_
    int count;
  };
  MPI_Comm comm_;
  int me_ = 0, nprocs_ = 1, slots_ = 0;
  std::vector<Partner> sources_, targets_;
  std::vector<int> sent_;    // the owned atoms each target asked for, one target after another
  std::vector<MPI_Request> requests_;
  std::vector<double> send_buffer_;
};

}    // namespace etd

#endif
