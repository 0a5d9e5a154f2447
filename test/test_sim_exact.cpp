/*
  The simulator's private shortcuts give exactly what they replace, bit for bit: every published figure rests on
  images that must not change by one pixel. vpSSLQuantise::quantise() against clamp(std::round()) on every value
  near a rounding boundary of the 8-bit range and on millions of others.
*/
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

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
