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
// exchange() then fills the slots of a per-atom vector from the owners' values.
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
        sources_.push_back({owner_rank[s], static_cast<int>(s), 0, {}});
      }
      sources_.back().count++;
    }
    slots_ = static_cast<int>(owner_rank.size());
    targets_.clear();
    if (nprocs_ == 1) return;

    // how many ranks will ask this one (each rank flags the owners it asks)
    std::vector<int> asks(nprocs_, 0);
    for (const Partner &p : sources_) asks[p.rank] = 1;
    int askers = 0;
    MPI_Reduce_scatter_block(asks.data(), &askers, 1, MPI_INT, MPI_SUM, comm_);

    std::vector<MPI_Request> sent(sources_.size());
    for (size_t k = 0; k < sources_.size(); k++)
      MPI_Isend(owner_index.data() + sources_[k].first, sources_[k].count, MPI_INT,
                sources_[k].rank, request_tag, comm_, &sent[k]);
    targets_.resize(askers);
    for (Partner &t : targets_) {
      MPI_Status status;
      MPI_Probe(MPI_ANY_SOURCE, request_tag, comm_, &status);
      MPI_Get_count(&status, MPI_INT, &t.count);
      t.rank = status.MPI_SOURCE;
      t.indices.resize(t.count);
      MPI_Recv(t.indices.data(), t.count, MPI_INT, t.rank, request_tag, comm_, MPI_STATUS_IGNORE);
    }
    MPI_Waitall(static_cast<int>(sent.size()), sent.data(), MPI_STATUSES_IGNORE);
  }

  // values[width * (offset + s) + k] = the owner's values[width * index + k] for every slot s
  // (values must hold offset + slots() atoms). Collective among the partners.
  void exchange(double *values, int offset, int width)
  {
    if (sources_.empty() && targets_.empty()) return;
    requests_.resize(sources_.size() + targets_.size());
    size_t n = 0;
    for (const Partner &p : sources_)
      MPI_Irecv(values + static_cast<size_t>(width) * (offset + p.first), width * p.count,
                MPI_DOUBLE, p.rank, values_tag, comm_, &requests_[n++]);
    size_t total = 0;
    for (const Partner &t : targets_) total += t.indices.size();
    send_buffer_.resize(width * total);
    double *buffer = send_buffer_.data();
    for (const Partner &t : targets_) {
      double *start = buffer;
      for (int index : t.indices)
        for (int k = 0; k < width; k++) *buffer++ = values[static_cast<size_t>(width) * index + k];
      MPI_Isend(start, width * t.count, MPI_DOUBLE, t.rank, values_tag, comm_, &requests_[n++]);
    }
    MPI_Waitall(static_cast<int>(n), requests_.data(), MPI_STATUSES_IGNORE);
  }

  int slots() const { return slots_; }
  // atoms this rank sends in one exchange
  int sent_atoms() const
  {
    int total = 0;
    for (const Partner &t : targets_) total += t.count;
    return total;
  }

 private:
  static constexpr int request_tag = 1, values_tag = 2;
  struct Partner {
    int rank;
    int first;    // sources: first slot
    int count;
    std::vector<int> indices;    // targets: the owned atoms it asked for
  };
  MPI_Comm comm_;
  int me_ = 0, nprocs_ = 1, slots_ = 0;
  std::vector<Partner> sources_, targets_;
  std::vector<MPI_Request> requests_;
  std::vector<double> send_buffer_;
};

}    // namespace etd

#endif
