/*
  The simulator's private shortcuts give exactly what they replace, bit for bit: every published figure rests on
  images that must not change by one pixel. vpSSLQuantise::quantise() against clamp(std::round()) on every value
  near a rounding boundary of the 8-bit range and on millions of others; vpSSLGaussRand against ViSP's vpGaussRand,
  whose sequence it reproduces, on some 30 million draws of several seeds, standard deviations and means, drawn one
  by one and in blocks; the SIMD kernels of the sensor noise and of the open-water shading against their scalar
  expressions; the renderer's open-water shortcut against its full shading of the same rays.
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
#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLScenario.h>

#include "vpSSLBlur.h"
#include "vpSSLGaussRand.h"
#include "vpSSLNoiseKernel.h"
#include "vpSSLQuantise.h"
#include "vpSSLSurfaceKernel.h"

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
  // NaN, for which the reference's cast is undefined, is black.
  EXPECT_EQ(vpSSLQuantise::quantise(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(vpSSLQuantise::quantise(-std::numeric_limits<double>::quiet_NaN()), 0);
  // Uniform values over the pixel range and beyond, and random bit patterns (every magnitude); NaN excluded (above).
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

namespace {
bool sameBits(double a, double b)
{
  uint64_t ba, bb;
  std::memcpy(&ba, &a, sizeof(a));
  std::memcpy(&bb, &b, sizeof(b));
  return ba == bb;
}
} // namespace

TEST(SimExact, GaussRandBlocksDrawWhatVispDraws)
{
  // vpSSLWaterModel's use is blocks of 3 x 1024 draws; here blocks of every size from 0 to 40 and some large and
  // odd ones (a pair split across two blocks), mixed with single draws, of several seeds.
  size_t total = 0;
  for (long seed : {0L, 1L, 42L, 1000003L * 77L + 5L, -1L}) {
    for (const std::pair<double, double> &sm : std::vector<std::pair<double, double>>{{1., 0.}, {2.5, -3.}}) {
      vpGaussRand visp(sm.first, sm.second, seed);
      vpSSLGaussRand blocks(sm.first, sm.second, seed);
      std::vector<size_t> sizes;
      for (size_t k = 0; k <= 40; ++k) {
        sizes.push_back(k);
      }
      for (size_t k : {1u, 3071u, 3072u, 1u, 3u, 5000u, 2u, 683u, 2048u, 1u, 1u}) {
        sizes.push_back(k);
      }
      std::vector<double> out;
      for (size_t round = 0; round < 3; ++round) {
        for (size_t k : sizes) {
          out.assign(k, 0.);
          blocks.draw(out.data(), k);
          for (size_t i = 0; i < k; ++i) {
            const double expected = visp();
            ASSERT_TRUE(sameBits(out[i], expected))
                << "seed " << seed << ", block of " << k << ", draw " << i << ": " << out[i] << " vs " << expected;
          }
          total += k;
          // A single draw between blocks: the generator is where the block left it.
          ASSERT_TRUE(sameBits(blocks(), visp())) << "seed " << seed << ", after a block of " << k;
          ++total;
        }
      }
    }
  }
  EXPECT_GT(total, size_t(300000));
}

TEST(SimExact, NoiseKernelsAreTheScalarExpressions)
{
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0., 1.);
  std::normal_distribution<double> normal(0., 1.);
  // Radiances: ordinary ones, zero and negative ones, values that land near the rounding boundaries and beyond the
  // 8-bit range, the infinities and NaN (a vector holding a NaN is done by the scalar expression).
  const size_t nb = 4099;
  std::vector<float> planes[3];
  for (std::vector<float> &p : planes) {
    p.resize(nb);
    for (size_t k = 0; k < nb; ++k) {
      const double pick = unit(rng);
      p[k] = pick < 0.7    ? static_cast<float>(unit(rng))
             : pick < 0.8  ? static_cast<float>(std::floor(unit(rng) * 255.) + 0.5) / 255.f
             : pick < 0.85 ? 0.f
             : pick < 0.9  ? -static_cast<float>(unit(rng))
             : pick < 0.95 ? static_cast<float>(1. + 10. * unit(rng))
                           : std::numeric_limits<float>::infinity();
    }
  }
  planes[0][17] = std::numeric_limits<float>::quiet_NaN();
  planes[2][2000] = -std::numeric_limits<float>::infinity();
  std::vector<double> deviates(3 * nb);
  for (double &x : deviates) {
    x = unit(rng) < 0.05 ? 0. : normal(rng);
  }
  for (const std::pair<double, double> &noise :
       std::vector<std::pair<double, double>>{{1. / 4000., 1. / (255. * 255.)}, {0., 0.}, {0.02, 1e-3}, {-1., -1.}}) {
    for (double gain : {1., 0.37, 64., 1. / 64.}) {
      std::vector<unsigned char> rgba(4 * nb, 7);
      vpSSLNoiseKernel::exposeQuantise(planes[0].data(), planes[1].data(), planes[2].data(), deviates.data(), nb, gain,
                                       noise.first, noise.second, rgba.data());
      for (size_t k = 0; k < nb; ++k) {
        for (int c = 0; c < 3; ++c) {
          const double y = gain * planes[c][k];
          const double sd = std::sqrt(std::max(0., noise.first * y + noise.second));
          ASSERT_EQ(rgba[4 * k + c], vpSSLQuantise::quantise(255. * (y + sd * deviates[3 * k + c])))
              << "pixel " << k << ", channel " << c << ", gain " << gain << ", radiance " << planes[c][k];
        }
        ASSERT_EQ(rgba[4 * k + 3], 255);
      }
    }
  }
  // The polar method's factors, on accepted squared radii in (0, 1) down to the smallest.
  std::vector<double> rsq(1001), logRsq(1001), fac(1001);
  for (size_t i = 0; i < rsq.size(); ++i) {
    rsq[i] = i == 0 ? std::numeric_limits<double>::denorm_min() : i == 1 ? 1e-300 : unit(rng);
    logRsq[i] = std::log(rsq[i]);
  }
  vpSSLNoiseKernel::polarFactors(rsq.data(), logRsq.data(), rsq.size(), fac.data());
  for (size_t i = 0; i < rsq.size(); ++i) {
    ASSERT_TRUE(sameBits(fac[i], std::sqrt(-2. * logRsq[i] / rsq[i]))) << rsq[i];
  }
}

TEST(SimExact, SurfaceKernelIsItsScalarShading)
{
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> unit(-1., 1.);
  vpSSLSurfaceKernel::Surface s{{0., -std::cos(0.3), std::sin(0.3)}, 3., 35. * 35., 1.333, 1e-12};
  // Rays of a camera's field of view and beyond: up and down, grazing the surface (sn . d near 0 and near eps),
  // inside and outside Snell's window, near and beyond the maximum range.
  const size_t count = 4099;
  std::vector<double> dx(count), dy(count), dz(count), fresnel(count), tw(count);
  for (size_t k = 0; k < count; ++k) {
    dx[k] = unit(rng);
    dy[k] = unit(rng);
    dz[k] = 1.;
    if (k % 7 == 0) {
      // On the surface's horizon, sn . d = 0 or within a few eps of it.
      dy[k] = (s.sn[2] * dz[k] - (k % 3) * 1e-12) / -s.sn[1];
    }
  }
  for (double num : {3., 0.2, 0., -1.}) {
    // Inside Snell's window the surface is met within 1.5 num of the camera: a 4 m range (16) cuts some of those.
    for (double maxRange2 : {35. * 35., 16., 4., std::numeric_limits<double>::infinity()}) {
      s.num = num;
      s.maxRange2 = maxRange2;
      vpSSLSurfaceKernel::surfaceRays(s, dx.data(), dy.data(), dz.data(), count, fresnel.data(), tw.data());
      size_t window = 0;
      for (size_t k = 0; k < count; ++k) {
        double t = 0.;
        const double expected = vpSSLSurfaceKernel::surfaceRay(s, dx[k], dy[k], dz[k], t);
        ASSERT_TRUE(sameBits(fresnel[k], expected)) << "ray " << k << ": " << fresnel[k] << " vs " << expected;
        if (expected >= 0.) {
          ASSERT_TRUE(sameBits(tw[k], t)) << "ray " << k << ": " << tw[k] << " vs " << t;
        }
        window += expected >= 0. && expected < 1.;
      }
      if (num > 0. && maxRange2 > 4. * num * num) {
        EXPECT_GT(window, count / 10) << "num " << num << ", max range^2 " << maxRange2;
      }
    }
  }
}

TEST(SimExact, OpenWaterShortcutIsTheFullShading)
{
  // The renderer leaves out the tests that cannot pass on pixels whose rays cannot meet the sheet (nor, after the
  // water surface, its mirror image); it takes the full shading everywhere when a backdrop is set. A backdrop
  // plane 1000 m behind a level camera is met by none of its rays, reflected or not: both renderers must give the
  // same image and ranges, bit for bit, whatever the pose.
  vpCameraParameters cam(554.3, 554.3, 320., 240.);
  vpSSLRenderer shortcut(cam, 640, 480), full(cam, 640, 480);
  vpImage<unsigned char> texture(8, 8, 200);
  full.setBackdrop(texture, 0.01);
  size_t pixels = 0, met = 0;
  // One ray per pixel (the closed loop's) and 4 x 4 (the default).
  for (unsigned int supersampling : {1u, 4u}) {
    for (vpSSLRenderer *r : {&shortcut, &full}) {
      r->setMaxRange(35.);
      r->setSupersampling(supersampling);
    }
    // Level camera (optical axis horizontal) looking north at the sheet (facing south), from several ranges, offsets,
    // depths and yaws; the surface 0.4-3 m above the sheet's centre.
    for (double range : {0.5, 1.2, 3., 8.}) {
      // The last yaw turns the camera away: the sheet and its mirror image behind it.
      for (double yaw : {0., 0.3, -0.6, 3.}) {
        for (double depthAbove : {0.4, 3.}) {
          for (double roll : {0., 0.2}) {
            // The world is North-East-Down with the surface at z = 0 (vpSSLScenario). The sheet faces south: its
            // axes, as a level camera's looking north, are x east, y down, z north.
            const vpRotationMatrix north({0., 0., 1., 1., 0., 0., 0., 1., 0.});
            const vpHomogeneousMatrix wMo(vpTranslationVector(0., 0., depthAbove), north);
            // The camera south of it, turned by yaw about the vertical and rolled about its optical axis.
            const vpHomogeneousMatrix wMc(
                vpTranslationVector(-range * std::cos(yaw), range * std::sin(yaw) * 0.5, depthAbove + 0.2),
                vpRotationMatrix(vpRxyzVector(0., 0., yaw)) * north * vpRotationMatrix(vpRxyzVector(0., 0., roll)));
            const vpHomogeneousMatrix cMo = wMc.inverse() * wMo;
            const vpPlane surface = vpSSLScenario::surfaceInTarget(wMo);
            // The backdrop 1000 m behind the camera, facing it.
            const vpHomogeneousMatrix oMb = cMo.inverse() * vpHomogeneousMatrix(0., 0., -1000., 0., 0., 0.);
            full.setBackdropPose(oMb);
            vpImage<float> r1, z1, r2, z2;
            vpImage<unsigned char> g1, g2;
            for (vpSSLRenderer *r : {&shortcut, &full}) {
              r->setWaterSurface(surface);
            }
            shortcut.render(cMo, r1, z1);
            full.render(cMo, r2, z2);
            shortcut.render(cMo, g1);
            full.render(cMo, g2);
            for (unsigned int i = 0; i < r1.getSize(); ++i) {
              ASSERT_TRUE(sameBits(r1.bitmap[i], r2.bitmap[i]))
                  << "reflectance of pixel " << i << ", supersampling " << supersampling << ", range " << range
                  << ", yaw " << yaw << ": " << r1.bitmap[i] << " vs " << r2.bitmap[i];
              ASSERT_TRUE(sameBits(z1.bitmap[i], z2.bitmap[i])) << "range of pixel " << i;
              ASSERT_EQ(g1.bitmap[i], g2.bitmap[i]) << "grey of pixel " << i;
              met += std::isfinite(z1.bitmap[i]);
            }
            pixels += r1.getSize();
          }
        }
      }
    }
  }
  // The sheet, or the sky through Snell's window, in a part of the images.
  EXPECT_GT(met, pixels / 50);
}

TEST(SimExact, BoxBlurIsTheWholeFrameBlur)
{
  // The plain separable blur of the whole frame, borders replicated, the sums taken in the same order.
  auto wholeFrame = [](const std::vector<float> &plane, int W, int H, double sigma, std::vector<float> &out) {
    const int r = static_cast<int>(std::ceil(3. * sigma));
    std::vector<float> k(2 * r + 1), across(plane.size());
    double sum = 0.;
    for (int i = -r; i <= r; ++i) {
      k[i + r] = static_cast<float>(std::exp(-0.5 * i * i / (sigma * sigma)));
      sum += k[i + r];
    }
    for (float &x : k) {
      x = static_cast<float>(x / sum);
    }
    for (int y = 0; y < H; ++y) {
      for (int x = 0; x < W; ++x) {
        float acc = 0.f;
        for (int i = -r; i <= r; ++i) {
          acc += k[i + r] * plane[y * W + std::min(std::max(x + i, 0), W - 1)];
        }
        across[y * W + x] = acc;
      }
    }
    for (int y = 0; y < H; ++y) {
      for (int x = 0; x < W; ++x) {
        float acc = 0.f;
        for (int i = -r; i <= r; ++i) {
          acc += k[i + r] * across[std::min(std::max(y + i, 0), H - 1) * W + x];
        }
        out[y * W + x] += acc;
      }
    }
  };
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  const int W = 64, H = 48;
  std::vector<float> tmp;
  size_t cases = 0;
  for (double sigma : {0., 0.5, 1., 2., 4., 16.}) {
    // Boxes inside the frame, touching each border, the whole frame, a single pixel, none; values with -0, negative
    // ones and a NaN.
    for (int shape = 0; shape < 9; ++shape) {
      std::vector<float> plane(W * H, 0.f), out(W * H), expected(W * H);
      int x0 = 20, x1 = 30, y0 = 10, y1 = 18;
      if (shape == 1) {
        x0 = 0;
      } else if (shape == 2) {
        x1 = W;
      } else if (shape == 3) {
        y0 = 0;
      } else if (shape == 4) {
        y1 = H;
      } else if (shape == 5) {
        x0 = y0 = 0;
        x1 = W;
        y1 = H;
      } else if (shape == 6) {
        x1 = x0 + 1;
        y1 = y0 + 1;
      } else if (shape == 7) {
        x1 = x0;
      }
      for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
          plane[y * W + x] = unit(rng) < 0.2f ? 0.f : unit(rng);
        }
      }
      plane[5] = -0.f;
      if (shape == 8) {
        plane[12 * W + 25] = -0.5f;
        plane[13 * W + 26] = std::numeric_limits<float>::quiet_NaN();
      }
      for (int p = 0; p < W * H; ++p) {
        out[p] = expected[p] = unit(rng) < 0.3f ? 0.f : unit(rng);
      }
      vpSSLBlur::addBlurred(plane, W, H, sigma, tmp, out.data());
      if (sigma > 0.) {
        wholeFrame(plane, W, H, sigma, expected);
      } else {
        // No blur: the plane itself is added.
        for (int p = 0; p < W * H; ++p) {
          expected[p] += plane[p];
        }
      }
      for (int p = 0; p < W * H; ++p) {
        ASSERT_TRUE(sameBits(out[p], expected[p]) || (std::isnan(out[p]) && std::isnan(expected[p])))
            << "sigma " << sigma << ", shape " << shape << ", pixel " << p % W << ", " << p / W << ": " << out[p]
            << " vs " << expected[p];
      }
      ++cases;
    }
  }
  EXPECT_EQ(cases, size_t(54));
}
