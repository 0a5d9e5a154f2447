/*
  The symmetry centring of a candidate (vpSSLSymmetryKernel::centre(), the SIMD search over every centre of the
  window at once) gives the outputs of a plain scalar search (below), bit for bit: the centre (u, v),
  the asymmetry and the return value, ties included (the first minimum in row-major order), on every SIMD target
  compiled in, for the discs of the full-resolution (radius 8) and small-landmark (16) modes and a few others, on
  noise, on images made of ties, on a rendered target and on a real photograph, up to the image border.
*/

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include "../modules/ssl/src/vpSSLSymmetryKernel.h"

namespace {
const double kFlatVariance = 225.; // vpSSLRadiusEstimatorGeometry.cpp's

struct Result
{
  bool ok;
  double u, v, asymmetry;
};

bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

// The reference search of vpSSLRadiusEstimator::symmetryCentre(), in plain scalar code: the
// energy of every centre in 64 bits over the half disc found by testing every pixel, the peak's own centre first
// and then the others, a later one winning only if lower or equal and earlier in row-major order; the disc's
// variance in doubles.
Result reference(const vpImage<unsigned char> &I, int radius, double u, double v)
{
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  const int reach = 6;
  const int cu = static_cast<int>(std::lround(2. * u)), cv = static_cast<int>(std::lround(2. * v));
  if (cu - reach < 2 * radius || cv - reach < 2 * radius || cu + reach > 2 * (W - 1 - radius) ||
      cv + reach > 2 * (H - 1 - radius)) {
    return {false, u, v, 0.};
  }
  auto energy = [&](int su, int sv) {
    const int pu = su >> 1, pv = sv >> 1, qu = (su >> 1) + (su & 1), qv = (sv >> 1) + (sv & 1);
    long e = 0;
    for (int dy = 0; dy <= radius; ++dy) {
      for (int dx = -radius; dx <= radius; ++dx) {
        if ((dy > 0 || dx > 0) && dx * dx + dy * dy <= radius * radius) {
          const long d = static_cast<long>(I[pv + dy][pu + dx]) - static_cast<long>(I[qv - dy][qu - dx]);
          e += d * d;
        }
      }
    }
    return e;
  };
  long bestE = energy(cu, cv);
  int bi = 0, bj = 0;
  for (int j = -reach; j <= reach; ++j) {
    for (int i = -reach; i <= reach; ++i) {
      const long e = energy(cu + i, cv + j);
      if (e < bestE || (e == bestE && (j < bj || (j == bj && i < bi)))) {
        bestE = e;
        bi = i;
        bj = j;
      }
    }
  }
  auto E = [&](int i, int j) { return static_cast<double>(energy(cu + i, cv + j)); };
  double du = 0., dv = 0.;
  const double b = static_cast<double>(bestE);
  if (bi > -reach && bi < reach) {
    const double a = E(bi - 1, bj), c = E(bi + 1, bj);
    const double den = a - 2. * b + c;
    du = den > 0. ? std::max(-0.5, std::min(0.5, 0.5 * (a - c) / den)) : 0.;
  }
  if (bj > -reach && bj < reach) {
    const double a = E(bi, bj - 1), c = E(bi, bj + 1);
    const double den = a - 2. * b + c;
    dv = den > 0. ? std::max(-0.5, std::min(0.5, 0.5 * (a - c) / den)) : 0.;
  }
  Result r{true, 0.5 * (cu + bi + du), 0.5 * (cv + bj + dv), 0.};
  const int pu = (cu + bi) >> 1, pv = (cv + bj) >> 1;
  double sum = 0., sum2 = 0.;
  int n = 0;
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      if (dx * dx + dy * dy <= radius * radius) {
        const double g = I[pv + dy][pu + dx];
        sum += g;
        sum2 += g * g;
        ++n;
      }
    }
  }
  const double variance = sum2 / n - (sum / n) * (sum / n);
  r.asymmetry = variance < kFlatVariance ? 0. : b / (0.5 * n * 2. * variance);
  return r;
}

struct Case
{
  const vpImage<unsigned char> *I;
  int radius;
  double u, v;
  Result expected;
  std::string what;
};

// Starting centres on a grid of step \e step (plus a fraction of a pixel that varies), from outside the border
// band to the far side, so that both the refusals and the windows that touch the border are met.
void addGrid(std::vector<Case> &cases, const vpImage<unsigned char> &I, int radius, int step, const std::string &what)
{
  vpUniRand rand(static_cast<long>(radius * 1000 + step));
  for (int v = radius - 4; v < static_cast<int>(I.getHeight()) - radius + 4; v += step) {
    for (int u = radius - 4; u < static_cast<int>(I.getWidth()) - radius + 4; u += step) {
      const double fu = u + rand.uniform(-0.5, 0.5), fv = v + rand.uniform(-0.5, 0.5);
      cases.push_back(
          {&I, radius, fu, fv, reference(I, radius, fu, fv),
           what + " r " + std::to_string(radius) + " at " + std::to_string(fu) + ", " + std::to_string(fv)});
    }
  }
}

// Runs every case on the current target; returns the number of mismatches (the first ones reported as failures
// if \e report).
int check(const std::vector<Case> &cases, const char *target, bool report = true)
{
  std::vector<int> spans;
  std::vector<int16_t> buffer;
  int spansRadius = -1, failures = 0;
  for (const Case &c : cases) {
    if (spansRadius != c.radius) {
      vpSSLSymmetryKernel::halfDisc(c.radius, spans);
      spansRadius = c.radius;
    }
    double u = c.u, v = c.v, asymmetry = -1.;
    const bool ok = vpSSLSymmetryKernel::centre(*c.I, c.radius, spans, kFlatVariance, buffer, u, v, asymmetry);
    if (ok != c.expected.ok || !sameBits(u, c.expected.u) || !sameBits(v, c.expected.v) ||
        !sameBits(asymmetry, c.expected.asymmetry)) {
      if (++failures <= 10 && report) {
        ADD_FAILURE() << target << ", " << c.what << ": got " << ok << " (" << u << ", " << v << ") " << asymmetry
                      << ", expected " << c.expected.ok << " (" << c.expected.u << ", " << c.expected.v << ") "
                      << c.expected.asymmetry;
      }
    }
  }
  return failures;
}

int checkEveryTarget(const std::vector<Case> &cases)
{
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  EXPECT_GE(targets.size(), 2u); // at least one SIMD target and the emulated or scalar fallback
  int failures = 0;
  for (int64_t t : targets) {
    hwy::SetSupportedTargetsForTest(t);
    failures += check(cases, hwy::TargetName(t));
  }
  hwy::SetSupportedTargetsForTest(0);
  return failures;
}

vpImage<unsigned char> noise(int width, int height, int levels, long seed)
{
  vpImage<unsigned char> I(static_cast<unsigned int>(height), static_cast<unsigned int>(width));
  vpUniRand rand(seed);
  for (unsigned int k = 0; k < I.getSize(); ++k) {
    I.bitmap[k] = static_cast<unsigned char>(rand.uniform(0, levels) * (255 / (levels - 1)));
  }
  return I;
}
} // namespace

TEST(SymmetryKernel, NoiseGivesTheScalarSearchOnEveryTarget)
{
  // Full grey range (no ties), then two levels 0 / 255 (the largest differences, many ties).
  const vpImage<unsigned char> grey = noise(97, 83, 256, 1), binary = noise(90, 77, 2, 2);
  std::vector<Case> cases;
  for (int radius : {8, 9, 13, 16}) {
    addGrid(cases, grey, radius, 5, "grey noise");
    addGrid(cases, binary, radius, 7, "binary noise");
  }
  // The comparison tells searches apart: the refusals near the border and the accepted centres are both there,
  // and another disc gives another answer.
  int accepted = 0, refused = 0, asymmetric = 0;
  for (const Case &c : cases) {
    (c.expected.ok ? accepted : refused)++;
    asymmetric += c.expected.asymmetry > 0.;
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(refused, 20);
  EXPECT_GT(asymmetric, 100);
  std::vector<Case> wrongDisc(cases.begin(), cases.begin() + 200);
  for (Case &c : wrongDisc) {
    c.radius = 10;
  }
  EXPECT_GT(check(wrongDisc, "default target, wrong disc", false), 0) << "the check cannot fail";
  EXPECT_EQ(checkEveryTarget(cases), 0);
}

TEST(SymmetryKernel, TiesResolveAsTheScalarSearchOnEveryTarget)
{
  // A flat image: every centre ties at 0 (the first of the window wins, no parabola); a periodic one whose period
  // divides the window: rows and columns of equal minima; few grey levels: ties among unequal patterns.
  vpImage<unsigned char> flat(60, 64, 128), stripes(60, 64), levels = noise(64, 60, 3, 3);
  for (unsigned int i = 0; i < stripes.getHeight(); ++i) {
    for (unsigned int j = 0; j < stripes.getWidth(); ++j) {
      stripes[i][j] = static_cast<unsigned char>(((i / 2 + j / 3) % 2) * 200 + 20);
    }
  }
  std::vector<Case> cases;
  for (int radius : {8, 16}) {
    addGrid(cases, flat, radius, 3, "flat");
    addGrid(cases, stripes, radius, 3, "stripes");
    addGrid(cases, levels, radius, 3, "three levels");
  }
  int cornerWins = 0;
  for (const Case &c : cases) {
    cornerWins += c.expected.ok && c.I == &flat && c.expected.u == 0.5 * (std::lround(2. * c.u) - 6);
  }
  EXPECT_GT(cornerWins, 10); // the flat image's first centre (row-major) wins
  EXPECT_EQ(checkEveryTarget(cases), 0);
}

TEST(SymmetryKernel, RenderedTargetAndPhotographGiveTheScalarSearchOnEveryTarget)
{
  // ssl3-a3 at 1 m (landmarks, their rings and the paper around them) and ViSP's AprilTag photograph (real
  // clutter, the peaks the detector mostly examines).
  vpImage<unsigned char> rendered, photo;
  vpSSLRenderer renderer(vpCameraParameters(600., 600., 159.5, 119.5), 320, 240);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.render(vpHomogeneousMatrix(0.02, -0.01, 1.0, vpMath::rad(10.), vpMath::rad(-8.), vpMath::rad(5.)), rendered);
  vpImageIo::read(photo, std::string(VISP_SSL_IMAGES_DIR) + "/AprilTag/AprilTag.pgm");
  std::vector<Case> cases;
  addGrid(cases, rendered, 8, 4, "rendered");
  addGrid(cases, rendered, 16, 6, "rendered");
  addGrid(cases, photo, 8, 9, "AprilTag.pgm");
  addGrid(cases, photo, 16, 17, "AprilTag.pgm");
  EXPECT_EQ(checkEveryTarget(cases), 0);
}
