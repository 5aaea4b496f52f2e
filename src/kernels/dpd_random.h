// ETD-DPD: counter-based pair noise from Random123 (Philox4x64-10).
//
// Each draw is a pure function of (seed, stream, smaller atom ID, larger atom ID, timestep):
// theta_ij = theta_ji on every rank, independent of decomposition, neighbour order, newton
// setting and restarts. Nothing is stored between calls.
#ifndef ETD_DPD_RANDOM_H
#define ETD_DPD_RANDOM_H

#include <Random123/philox.h>
#include <boost/random/normal_distribution.hpp>

#include <cstdint>

namespace etd {

// Streams keep the users of one seed apart (pair noise, FPM matrix noise, integrator noise,
// wall-layer velocities).
enum class NoiseStream : std::uint64_t {
  PairScalar = 1,
  PairMatrix = 2,
  Integrator = 3,
  WallLayer = 4
};

class PairNoise {
 public:
  using Generator = r123::Philox4x64;

  PairNoise(std::uint64_t seed = 0, NoiseStream stream = NoiseStream::PairScalar)
  {
    key_ = {{seed, static_cast<std::uint64_t>(stream)}};
  }

  // Four independent unit Gaussians for pair (i, j) at a timestep, drawn like gaussian() (so
  // with group 0 the first one is gaussian()'s theta_ij); 'group' selects further, disjoint
  // groups of four (each group owns 2^32 Philox blocks).
  void gaussians4(std::int64_t tag_i, std::int64_t tag_j, std::int64_t timestep,
                  std::uint64_t group, double out[4]) const
  {
    BlockEngine words(*this, tag_i, tag_j, timestep, group << 32);
    boost::random::normal_distribution<double> normal;
    for (int k = 0; k < 4; k++) out[k] = normal(words);
  }

  // One unit Gaussian for pair (i, j): the scalar DPD noise theta_ij. Boost.Random's ziggurat
  // needs one 64-bit word almost always (no log, no sine), so a single Philox block serves the
  // pair; the rare further words come from the following blocks. The draw stays a pure
  // function of (seed, stream, pair, timestep).
  double gaussian(std::int64_t tag_i, std::int64_t tag_j, std::int64_t timestep) const
  {
    BlockEngine words(*this, tag_i, tag_j, timestep);
    return boost::random::normal_distribution<double>()(words);
  }

  // The words of successive Philox blocks of one pair and timestep as a uniform random bit
  // generator (what C++ and Boost distributions consume).
  class BlockEngine {
   public:
    using result_type = std::uint64_t;
    BlockEngine(const PairNoise &noise, std::int64_t tag_i, std::int64_t tag_j,
                std::int64_t timestep, std::uint64_t first_block = 0) :
        noise_(noise),
        tag_i_(tag_i), tag_j_(tag_j), timestep_(timestep), block_(first_block)
    {
    }
    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return ~result_type(0); }
    result_type operator()()
    {
      if (used_ == 4) {
        words_ = noise_.draw(tag_i_, tag_j_, timestep_, block_++);
        used_ = 0;
      }
      return words_.v[used_++];
    }

   private:
    const PairNoise &noise_;
    std::int64_t tag_i_, tag_j_, timestep_;
    std::uint64_t block_;
    Generator::ctr_type words_{};
    int used_ = 4;
  };

 private:
  Generator::ctr_type draw(std::int64_t tag_i, std::int64_t tag_j, std::int64_t timestep,
                           std::uint64_t block) const
  {
    const std::uint64_t lo = static_cast<std::uint64_t>(tag_i < tag_j ? tag_i : tag_j);
    const std::uint64_t hi = static_cast<std::uint64_t>(tag_i < tag_j ? tag_j : tag_i);
    const Generator::ctr_type counter = {{lo, hi, static_cast<std::uint64_t>(timestep), block}};
    return Generator()(counter, key_);
  }

  Generator::key_type key_;
};

}    // namespace etd

#endif
