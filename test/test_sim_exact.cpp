/*
  The simulator's private shortcuts give exactly what they replace, bit for bit: every published figure rests on
  images that must not change by one pixel. vpSSLQuantise::quantise() against clamp(std::round()) on every value
  near a rounding boundary of the 8-bit range and on millions of others; vpSSLGaussRand against ViSP's vpGaussRand,
  whose sequence it reproduces, on some 30 million draws of several seeds, standard deviations and means.
*/
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/core/vpGaussRand.h>

#include "vpSSLGaussRand.h"
#include "vpSSLQuantise.h"

namespace {
// The expression quantise() replaces.
unsigned char reference(double v)
{
  const double g = std::round(v);
  return static_cast<unsigned char>(g < 0. ? 0. : (g > 255. ? 255. : g));
}
} // namespace

TEST(SimExact, QuantiseIsClampOfRoundNearEveryBoundary)
{
  // Every half-integer and integer of [-300, 300] and its 64 nearest doubles on either side.
  size_t nb = 0;
  for (int k = -600; k <= 600; ++k) {
    const double centre = 0.5 * k;
    double below = centre, above = centre;
    for (int i = 0; i <= 64; ++i) {
      ASSERT_EQ(vpSSLQuantise::quantise(below), reference(below)) << below;
      ASSERT_EQ(vpSSLQuantise::quantise(above), reference(above)) << above;
      below = std::nextafter(below, -std::numeric_limits<double>::infinity());
      above = std::nextafter(above, std::numeric_limits<double>::infinity());
      nb += 2;
    }
  }
  EXPECT_GT(nb, 150000u);
}

TEST(SimExact, QuantiseIsClampOfRoundEverywhere)
{
  const double inf = std::numeric_limits<double>::infinity();
  for (double v : {0.,
                   -0.,
                   0.5,
                   -0.5,
                   254.5,
                   255.,
                   255.5,
                   256.,
                   -1e300,
                   1e300,
                   inf,
                   -inf,
                   std::numeric_limits<double>::denorm_min(),
                   -std::numeric_limits<double>::denorm_min(),
                   std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::lowest(),
                   4503599627370496.5,
                   9007199254740993.,
                   2147483648.,
                   -2147483649.}) {
    EXPECT_EQ(vpSSLQuantise::quantise(v), reference(v)) << v;
  }
  // Uniform values over the pixel range and beyond, and random bit patterns (every magnitude); NaN excluded, where
  // both take the same std::round expression.
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> pixel(-20., 280.);
  for (int i = 0; i < 4000000; ++i) {
    const double v = pixel(gen);
    ASSERT_EQ(vpSSLQuantise::quantise(v), reference(v)) << v;
  }
  for (int i = 0; i < 4000000; ++i) {
    const uint64_t bits = gen();
    double v;
    static_assert(sizeof(v) == sizeof(bits), "64-bit double");
    std::memcpy(&v, &bits, sizeof(v));
    if (std::isnan(v)) {
      continue;
    }
    ASSERT_EQ(vpSSLQuantise::quantise(v), reference(v)) << v;
  }
}

namespace {
// Draws of vpSSLGaussRand(sigma, mean, seed) and vpGaussRand(sigma, mean, seed) compared as bit patterns.
void expectSameDraws(double sigma, double mean, long seed, size_t nb)
{
  vpGaussRand visp(sigma, mean, seed);
  vpSSLGaussRand inlined(sigma, mean, seed);
  for (size_t i = 0; i < nb; ++i) {
    const double a = visp(), b = inlined();
    uint64_t ba, bb;
    std::memcpy(&ba, &a, sizeof(a));
    std::memcpy(&bb, &b, sizeof(b));
    ASSERT_EQ(ba, bb) << "draw " << i << " of seed " << seed << ", sigma " << sigma << ", mean " << mean << ": " << a
                      << " vs " << b;
  }
}
} // namespace

TEST(SimExact, GaussRandDrawsWhatVispDraws)
{
  // vpSSLWaterModel's use: sigma 1, mean 0, one generator per frame seeded as the simulators seed it (small
  // seeds, seed * 1000003 + frame, negative and 64-bit ones), 3 draws per pixel of a 640 x 480 frame and more.
  size_t total = 0;
  for (long seed : {0L, 1L, 11L, 42L, 1000003L + 7L, 100004L * 1000003L + 2399L, -1L, -123456789L,
                    static_cast<long>(0x7fffffffffffffffLL), static_cast<long>(-0x7fffffffffffffffLL - 1)}) {
    expectSameDraws(1., 0., seed, 3 * 640 * 480 + 1);
    total += 3 * 640 * 480 + 1;
  }
  // Other standard deviations and means (the scaling sigma * x + mean), odd draw counts.
  for (const std::pair<double, double> &sm : std::vector<std::pair<double, double>>{
           {0.02, 0.}, {2.5, -3.}, {1e-3, 1e3}, {0., 0.}, {1., -0.}, {0.3333333333333333, 0.1}}) {
    expectSameDraws(sm.first, sm.second, 1234567, 1000001);
    total += 1000001;
  }
  // A long stream: 2^24 draws of one generator.
  expectSameDraws(1., 0., 99, size_t(1) << 24);
  total += size_t(1) << 24;
  EXPECT_GT(total, size_t(25000000));
}
