// ETD-DPD: unit Gaussians by Boost.Random's ziggurat, in code that also compiles for a GPU.
//
// The pair noise must be the same number on a CPU and on a device: the same pair, timestep and
// seed give the same force there. Boost's normal_distribution<double> draws from 64-bit words
// with a 128-layer ziggurat (and an exponential ziggurat of 256 layers for its tail), but it
// reads its tables as static arrays of the host and cannot run in device code. These functions
// follow its algorithm step by step, with the tables passed in: Boost's own arrays on the host
// (ZigguratTables::host()), a copy in device memory on a GPU. From the same words they return
// the same doubles as Boost (unittest/test_math.cpp compares them over millions of draws,
// tails included). On a device, exp() may differ from the host's in the last bit; a draw can
// then differ only where the test y < exp(...) falls within that bit (rarely: it is reached in
// about 1 % of draws).
//
// Engine: a callable returning std::uint64_t words, the full 64-bit range (PairNoise's).
#ifndef ETD_NORMAL_ZIGGURAT_H
#define ETD_NORMAL_ZIGGURAT_H

#include "host_device.h"

#include <boost/random/exponential_distribution.hpp>
#include <boost/random/normal_distribution.hpp>

#include <cmath>
#include <cstdint>

namespace etd {

// The ziggurats' layer tables: x and y of the normal one (129 entries each) and of the
// exponential one (257 each), as Boost.Random defines them.
struct ZigguratTables {
  static constexpr int NORMAL_SIZE = 129;
  static constexpr int EXPONENTIAL_SIZE = 257;
  const double *normal_x = nullptr, *normal_y = nullptr;
  const double *exponential_x = nullptr, *exponential_y = nullptr;

  // Boost's own arrays, in host memory
  static ZigguratTables host()
  {
    using boost::random::detail::exponential_table;
    using boost::random::detail::normal_table;
    return {normal_table<double>::table_x, normal_table<double>::table_y,
            exponential_table<double>::table_x, exponential_table<double>::table_y};
  }
};

namespace ziggurat {

  // a * b rounded on its own, never fused with a following addition
  ETD_HOST_DEVICE inline double mul(double a, double b)
  {
#if defined(__CUDA_ARCH__)
    return __dmul_rn(a, b);
#else
    return a * b;
#endif
  }

  // Boost's generate_int_float_pair<double, 8> for a full-range 64-bit engine: the low byte of
  // one word is the layer (with the sign, for the normal), its upper 56 bits scaled to [0, 1) the
  // abscissa, after Boost's bookkeeping of spare bits has cleared bit 11.
  template <class Engine> ETD_HOST_DEVICE inline double int_float_pair(Engine &words, int &layer)
  {
    std::uint64_t u = words();
    layer = static_cast<int>(u & 0xffu);
    u &= ~(std::uint64_t(1) << 11);
    return static_cast<double>(u >> 8) * (1.0 / 72057594037927936.0);    // 2^-56
  }

  // Boost's uniform_01<double> on a 64-bit engine: a word times 2^-64, drawn again if that rounds
  // to 1.
  template <class Engine> ETD_HOST_DEVICE inline double uniform01(Engine &words)
  {
    for (;;) {
      const double r = static_cast<double>(words()) * (1.0 / 18446744073709551616.0);    // 2^-64
      if (r < 1.0) return r;
    }
  }

  // Boost's unit_exponential_distribution<double>.
  template <class Engine>
  ETD_HOST_DEVICE inline double unit_exponential(Engine &words, const ZigguratTables &t)
  {
    const double *tx = t.exponential_x, *ty = t.exponential_y;
    double shift = 0.0;
    for (;;) {
      int i;
      const double abscissa = int_float_pair(words, i);    // sets i first
      const double x = abscissa * tx[i];
      if (x < tx[i + 1]) return shift + x;
      if (i == 0) {
        shift += tx[1];    // the tail of an exponential is the body again, shifted
      } else {
        const double y01 = uniform01(words);
        const double y = ty[i] + mul(y01, ty[i + 1] - ty[i]);
        const double above_upper = mul(tx[i] - tx[i + 1], y01) - (tx[i] - x);
        const double above_lower = y - (ty[i + 1] + mul(tx[i + 1] - x, ty[i + 1]));
        if (above_upper < 0 && (above_lower < 0 || y < std::exp(-x))) return x + shift;
      }
    }
  }

  // Boost's normal tail beyond the first layer: rejection from an exponential shifted there.
  template <class Engine>
  ETD_HOST_DEVICE inline double normal_tail(Engine &words, const ZigguratTables &t)
  {
    const double tail_start = t.normal_x[1];
    for (;;) {
      const double x = unit_exponential(words, t) / tail_start;
      const double y = unit_exponential(words, t) / 1.0;
      if (2 * y > mul(x, x)) return x + tail_start;
    }
  }

}    // namespace ziggurat

// One unit Gaussian: Boost's normal_distribution<double>(0, 1) applied to words.
template <class Engine>
ETD_HOST_DEVICE inline double unit_normal(Engine &words, const ZigguratTables &t)
{
  const double *tx = t.normal_x, *ty = t.normal_y;
  for (;;) {
    int i;
    const double abscissa = ziggurat::int_float_pair(words, i);
    const int sign = (i & 1) * 2 - 1;
    i >>= 1;
    const double x = abscissa * tx[i];
    // normal_distribution(0, 1) returns unit * 1 + 0 (so -0 comes out as +0)
    if (x < tx[i + 1]) return ziggurat::mul(x * sign, 1.0) + 0.0;
    if (i == 0) return ziggurat::mul(ziggurat::normal_tail(words, t) * sign, 1.0) + 0.0;

    using ziggurat::mul;
    const double y01 = ziggurat::uniform01(words);
    const double y = ty[i] + mul(y01, ty[i + 1] - ty[i]);
    // the layer's convex part (with the inflection) and its concave part swap the bounds
    const double chord = mul(tx[i] - tx[i + 1], y01) - (tx[i] - x);
    const double tangent = y - (ty[i] + mul(mul(tx[i] - x, ty[i]), tx[i]));
    const double above_upper = tx[i] >= 1 ? chord : tangent;
    const double above_lower = tx[i] >= 1 ? tangent : chord;
    if (above_upper < 0 && (above_lower < 0 || y < std::exp(-(mul(x, x) / 2))))
      return mul(x * sign, 1.0) + 0.0;
  }
}

}    // namespace etd

#endif
