// PartnerExchange (src/partner_exchange.h): each rank receives exactly the values of the remote
// atoms it asked for, in its slots, for any pattern of requests, whether it packs the values
// sent (exchange()) or the caller does (swap()); run on 1, 2 and 4 ranks.
#include "partner_exchange.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <random>
#include <stdexcept>
#include <vector>

namespace {

int owned_atoms(int rank)
{
  return 10 + 3 * rank;
}
double value_of(int rank, int index, int k)
{
  return 1000.0 * rank + index + 0.25 * k;
}

// Asks every other rank (but, depending on the round, not all of them) for a random selection of
// its atoms, some twice over, and checks what arrives.
void exchange_round(etd::PartnerExchange &exchange, int round)
{
  int me = 0, nprocs = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  std::mt19937 random(17 * me + 101 * round);
  std::vector<int> owner_rank, owner_index;
  for (int p = 0; p < nprocs; p++) {
    if (p == me || (p + me + round) % 3 == 0) continue;    // some owners are not asked at all
    const int count = 1 + static_cast<int>(random() % 7);
    for (int c = 0; c < count; c++) {
      owner_rank.push_back(p);
      owner_index.push_back(static_cast<int>(random() % owned_atoms(p)));
    }
  }
  exchange.set_requests(owner_rank, owner_index);
  ASSERT_EQ(exchange.slots(), static_cast<int>(owner_rank.size()));

  const int width = 2 + round % 2;
  const int nlocal = owned_atoms(me);
  std::vector<double> values(width * (nlocal + owner_rank.size()), -1.0);
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < width; k++) values[width * i + k] = value_of(me, i, k);
  exchange.exchange(values.data(), nlocal, width);
  for (size_t s = 0; s < owner_rank.size(); s++)
    for (int k = 0; k < width; k++)
      EXPECT_EQ(values[width * (nlocal + s) + k], value_of(owner_rank[s], owner_index[s], k))
          << "rank " << me << " slot " << s << " round " << round;
  // the owned values are left alone
  for (int i = 0; i < nlocal; i++) EXPECT_EQ(values[width * i], value_of(me, i, 0));

  // the same through swap(), the caller packing the values of sent() in its order
  std::vector<double> packed, slots(width * owner_rank.size(), -1.0);
  for (int index : exchange.sent())
    for (int k = 0; k < width; k++) packed.push_back(value_of(me, index, k));
  exchange.swap(packed.data(), slots.data(), width);
  for (size_t s = 0; s < owner_rank.size(); s++)
    for (int k = 0; k < width; k++)
      EXPECT_EQ(slots[width * s + k], value_of(owner_rank[s], owner_index[s], k))
          << "rank " << me << " slot " << s << " round " << round << " (swap)";

  // what this rank sends equals what the others asked of it
  int asked_of_me = 0, sent = static_cast<int>(exchange.sent().size());
  std::vector<int> asked(nprocs, 0), total(nprocs, 0);
  for (int p : owner_rank) asked[p]++;
  MPI_Allreduce(asked.data(), total.data(), nprocs, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  asked_of_me = total[me];
  EXPECT_EQ(sent, asked_of_me);
  EXPECT_EQ(exchange.idle(), owner_rank.empty() && sent == 0);
}

}    // namespace

TEST(PartnerExchange, DeliversTheRequestedValuesForAnyPattern)
{
  etd::PartnerExchange exchange(MPI_COMM_WORLD);
  // plans are replaced as the neighbor lists are rebuilt
  for (int round = 0; round < 4; round++) exchange_round(exchange, round);
}

TEST(PartnerExchange, RefusesSlotsOwnedByThisRankOrScattered)
{
  int me = 0, nprocs = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  etd::PartnerExchange exchange(MPI_COMM_WORLD);
  // (checked before any communication, so every rank throws alike)
  EXPECT_THROW(exchange.set_requests({me}, {0}), std::invalid_argument);
  EXPECT_THROW(exchange.set_requests({nprocs}, {0}), std::invalid_argument);
  if (nprocs >= 3) {
    const int a = (me + 1) % nprocs, b = (me + 2) % nprocs;
    EXPECT_THROW(exchange.set_requests({a, b, a}, {0, 0, 1}), std::invalid_argument);
  }
  // with no requests anywhere the exchange is a no-op
  exchange.set_requests({}, {});
  std::vector<double> values(3, 7.0);
  exchange.exchange(values.data(), 1, 3);
  EXPECT_EQ(values[0], 7.0);
  EXPECT_EQ(exchange.slots(), 0);
  EXPECT_TRUE(exchange.idle());
}
