// ETD-DPD: counter-based pair noise from Random123 (Philox2x64-10, Philox4x64-10).
//
// Each draw is a pure function of (seed, stream, smaller atom ID, larger atom ID, timestep):
// theta_ij = theta_ji on every rank, independent of decomposition, neighbour order, newton
// setting and restarts. Nothing is stored between calls.
//
// Draws come from Philox2x64-10, with both atom IDs packed in one counter word: half the
// multiplications of Philox4x64-10 at the same number of rounds, which is a quarter of the
// cost of a pair's noise in the pair loop (bench/README.md). Arguments that do not pack
// (PairNoise::packs) take Philox4x64-10.
#ifndef ETD_DPD_RANDOM_H
#define ETD_DPD_RANDOM_H

#include "host_device.h"
#include "normal_ziggurat.h"

#include <Random123/philox.h>

#include <cstdint>

namespace etd {

// Philox2x64's key is one word: the seed and the stream share it (the stream in the low byte).
ETD_HOST_DEVICE inline std::uint64_t scalar_noise_key(std::uint64_t seed, std::uint64_t stream)
{
  return (seed << 8) | (stream & 0xff);
}

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
  using Generator = r123::Philox4x64;          // arguments that do not pack
  using ScalarGenerator = r123::Philox2x64;    // the rest: nearly every draw

  PairNoise(std::uint64_t seed = 0, NoiseStream stream = NoiseStream::PairScalar)
  {
    key_ = {{seed, static_cast<std::uint64_t>(stream)}};
    scalar_key_ = {{scalar_noise_key(seed, static_cast<std::uint64_t>(stream))}};
  }

  // The ziggurat's tables: Boost's in host memory unless given a copy (in device memory, for a
  // GPU kernel; normal_ziggurat.h).
  void use_tables(const ZigguratTables &tables) { tables_ = tables; }

  // Four independent unit Gaussians for pair (i, j) at a timestep, drawn like gaussian() (so
  // with group 0 the first one is gaussian()'s theta_ij); 'group' (0-255) selects further,
  // disjoint groups of four.
  ETD_HOST_DEVICE void gaussians4(std::int64_t tag_i, std::int64_t tag_j, std::int64_t timestep,
                                  std::uint64_t group, double out[4]) const
  {
    const std::uint64_t lo = static_cast<std::uint64_t>(tag_i < tag_j ? tag_i : tag_j);
    const std::uint64_t hi = static_cast<std::uint64_t>(tag_i < tag_j ? tag_j : tag_i);
    if (packs(hi, timestep, group)) {
      ScalarEngine words(scalar_key_, lo | (hi << 32), packed_time(timestep, group));
      for (int k = 0; k < 4; k++) out[k] = unit_normal(words, tables_);
    } else {
      BlockEngine words(*this, tag_i, tag_j, timestep, group << 32);
      for (int k = 0; k < 4; k++) out[k] = unit_normal(words, tables_);
    }
  }

  // One unit Gaussian for pair (i, j): the scalar DPD noise theta_ij. Boost.Random's ziggurat
  // (normal_ziggurat.h draws what it draws) needs one 64-bit word almost always (no log, no
  // sine), so a single Philox block serves the pair; the rare further words come from the
  // following blocks. The draw stays a pure function of (seed, stream, pair, timestep).
  ETD_HOST_DEVICE double gaussian(std::int64_t tag_i, std::int64_t tag_j,
                                  std::int64_t timestep) const
  {
    const std::uint64_t lo = static_cast<std::uint64_t>(tag_i < tag_j ? tag_i : tag_j);
    const std::uint64_t hi = static_cast<std::uint64_t>(tag_i < tag_j ? tag_j : tag_i);
    if (packs(hi, timestep, 0)) {
      ScalarEngine words(scalar_key_, lo | (hi << 32), packed_time(timestep, 0));
      return unit_normal(words, tables_);
    }
    BlockEngine words(*this, tag_i, tag_j, timestep);
    return unit_normal(words, tables_);
  }

  // Philox2x64's counter holds (smaller ID | larger ID << 32, timestep | group << 48 | block <<
  // 56): IDs below 2^32, timesteps below 2^48 and groups below 256 fit; anything else (LAMMPS
  // built with 64-bit IDs and more than 4e9 atoms) takes Philox4x64, whose counter has a word
  // for each. Either way a draw is a pure function of its arguments.
  ETD_HOST_DEVICE static bool packs(std::uint64_t larger_id, std::int64_t timestep,
                                    std::uint64_t group)
  {
    return (larger_id >> 32) == 0 && timestep >= 0 && (timestep >> 48) == 0 && group < 256;
  }
  ETD_HOST_DEVICE static std::uint64_t packed_time(std::int64_t timestep, std::uint64_t group)
  {
    return static_cast<std::uint64_t>(timestep) | (group << 48);
  }

  // Philox2x64 blocks for one packed pair and timestep, as a uniform random bit generator; the
  // block number sits in the top byte of the timestep word (a draw needing more than 256 blocks,
  // 512 ziggurat tries, would wrap; the chance is far below 1e-300).
  class ScalarEngine {
   public:
    using result_type = std::uint64_t;
    ETD_HOST_DEVICE ScalarEngine(const ScalarGenerator::key_type &key, std::uint64_t pair,
                                 std::uint64_t timestep) :
        key_(key),
        counter_{{pair, timestep}}
    {
    }
    ETD_HOST_DEVICE static constexpr result_type min() { return 0; }
    ETD_HOST_DEVICE static constexpr result_type max() { return ~result_type(0); }
    ETD_HOST_DEVICE result_type operator()()
    {
      if (used_ == 2) {
        words_ = ScalarGenerator()(counter_, key_);
        counter_.v[1] += std::uint64_t(1) << 56;
        used_ = 0;
      }
      return words_.v[used_++];
    }

   private:
    const ScalarGenerator::key_type &key_;
    ScalarGenerator::ctr_type counter_;
    ScalarGenerator::ctr_type words_{};
    int used_ = 2;
  };

  // The words of successive Philox blocks of one pair and timestep as a uniform random bit
  // generator (what C++ and Boost distributions consume).
  class BlockEngine {
   public:
    using result_type = std::uint64_t;
    ETD_HOST_DEVICE BlockEngine(const PairNoise &noise, std::int64_t tag_i, std::int64_t tag_j,
                                std::int64_t timestep, std::uint64_t first_block = 0) :
        noise_(noise),
        tag_i_(tag_i), tag_j_(tag_j), timestep_(timestep), block_(first_block)
    {
    }
    ETD_HOST_DEVICE static constexpr result_type min() { return 0; }
    ETD_HOST_DEVICE static constexpr result_type max() { return ~result_type(0); }
    ETD_HOST_DEVICE result_type operator()()
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
  ETD_HOST_DEVICE Generator::ctr_type draw(std::int64_t tag_i, std::int64_t tag_j,
                                           std::int64_t timestep, std::uint64_t block) const
  {
    const std::uint64_t lo = static_cast<std::uint64_t>(tag_i < tag_j ? tag_i : tag_j);
    const std::uint64_t hi = static_cast<std::uint64_t>(tag_i < tag_j ? tag_j : tag_i);
    const Generator::ctr_type counter = {{lo, hi, static_cast<std::uint64_t>(timestep), block}};
    return Generator()(counter, key_);
  }

  Generator::key_type key_;
  ScalarGenerator::key_type scalar_key_;
  ZigguratTables tables_ = ZigguratTables::host();
};

}    // namespace etd

#endif
