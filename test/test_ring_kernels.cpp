/*
  The SIMD kernels of the ring reading and of the peak search give the results of a plain scalar
  reference (below), bit for bit, on every SIMD target compiled in:
  - vpSSLRayKernel::sample(): the bilinear samples of a ray, out to the image's last row and column and its very
    last pixel (where a gathered word would end past the image), on noise, a rendered target and a photograph;
  - vpSSLRayKernel::screen(): the radii of a grid at which the reference ring test goes on past its first two ring
    pairs, on
    random profiles, the rays of a rendered landmark and of a photograph, including radii too small for three rings
    and profiles whose last sample is reached;
  - vpSSLRayKernel::score(): of those, the radii that the reference ring test and the tests rayCandidates() runs on its
    result accept, and their scores;
  - vpSSLPeakKernel::localMaxima(): the local maxima of a row, ties and plateaus included, with and without the
    neighbouring rows.
*/

#include <algorithm>
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

#include "../modules/ssl/src/vpSSLPeakKernel.h"
#include "../modules/ssl/src/vpSSLRayKernel.h"

namespace {
const double kCos[8] = {1., M_SQRT1_2, 0., -M_SQRT1_2, -1., -M_SQRT1_2, 0., M_SQRT1_2};
const double kSin[8] = {0., M_SQRT1_2, 1., M_SQRT1_2, 0., -M_SQRT1_2, -1., -M_SQRT1_2};

// Runs f() once per SIMD target compiled in (and the scalar fallback); returns the number of failures.
template <typename F> int onEveryTarget(F &&f)
{
  std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  EXPECT_GE(targets.size(), 2u); // at least one SIMD target and the scalar fallback
  int failures = 0;
  for (int64_t t : targets) {
    hwy::SetSupportedTargetsForTest(t);
    failures += f(hwy::TargetName(t));
  }
  hwy::SetSupportedTargetsForTest(0);
  return failures;
}

bool sameBits(float a, float b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// vpSSLRadiusEstimator::ray()'s samples as they were, in plain scalar code.
float referenceSample(const vpImage<unsigned char> &I, double u, double v, int d, double step, size_t i)
{
  const int lastU = static_cast<int>(I.getWidth()) - 1, lastV = static_cast<int>(I.getHeight()) - 1;
  const double rho = static_cast<double>(i) * step;
  const double x = u + rho * kCos[d], y = v + rho * kSin[d];
  const int u0 = static_cast<int>(x), v0 = static_cast<int>(y);
  const double fu = x - u0, fv = y - v0;
  const int u1 = std::min(u0 + 1, lastU), v1 = std::min(v0 + 1, lastV);
  const double top = (1. - fu) * I[v0][u0] + fu * I[v0][u1];
  const double bottom = (1. - fu) * I[v1][u0] + fu * I[v1][u1];
  return static_cast<float>((1. - fv) * top + fv * bottom);
}

// Samples of the ray from (u, v) along d that lie inside the image, every `step` px.
size_t raySamples(const vpImage<unsigned char> &I, double u, double v, int d, double step)
{
  const double W = I.getWidth() - 1., H = I.getHeight() - 1.;
  size_t n = 0;
  for (;; ++n) {
    const double rho = static_cast<double>(n) * step, x = u + rho * kCos[d], y = v + rho * kSin[d];
    if (x < 0. || y < 0. || x > W || y > H) {
      return n;
    }
  }
}

struct RayCase
{
  const vpImage<unsigned char> *I;
  double u, v;
  int d;
  std::string name;
};

int checkSamples(const std::vector<RayCase> &cases, const char *target)
{
  int failures = 0;
  std::vector<float> got;
  for (const RayCase &c : cases) {
    const double step = 0.5;
    const size_t n = raySamples(*c.I, c.u, c.v, c.d, step);
    got.assign(n + 1, -1.f);
    const vpSSLRayKernel::Ray ray = {c.I->bitmap,
                                     static_cast<int>(c.I->getWidth()),
                                     static_cast<int>(c.I->getHeight()),
                                     c.u,
                                     c.v,
                                     kCos[c.d],
                                     kSin[c.d],
                                     step};
    // In two calls, the second starting where the first ended (ray() reads a ray in parts).
    const size_t half = n / 3;
    vpSSLRayKernel::sample(ray, 0, half, got.data());
    vpSSLRayKernel::sample(ray, half, n, got.data());
    for (size_t i = 0; i < n; ++i) {
      const float expected = referenceSample(*c.I, c.u, c.v, c.d, step, i);
      if (!sameBits(got[i], expected)) {
        ADD_FAILURE() << target << ", " << c.name << ", centre (" << c.u << ", " << c.v << "), ray " << c.d
                      << ", sample " << i << " of " << n << ": " << got[i] << " instead of " << expected;
        ++failures;
        break;
      }
    }
    if (got[n] != -1.f) {
      ADD_FAILURE() << target << ", " << c.name << ": wrote past the last sample";
      ++failures;
    }
  }
  return failures;
}

void addRays(std::vector<RayCase> &cases, const vpImage<unsigned char> &I, const std::string &name, int nbCentres,
             long seed)
{
  vpUniRand rand(seed);
  const double W = I.getWidth() - 1., H = I.getHeight() - 1.;
  std::vector<std::pair<double, double>> centres = {{0., 0.}, {W, H}, {W, 0.}, {0., H}, {0.5 * W, 0.5 * H}};
  for (int k = 0; k < nbCentres; ++k) {
    // Integer, half-integer and arbitrary centres.
    double u = rand.uniform(0., W), v = rand.uniform(0., H);
    if (k % 3 == 0) {
      u = std::floor(u);
      v = std::floor(v);
    } else if (k % 3 == 1) {
      u = 0.5 * std::floor(2. * u);
      v = 0.5 * std::floor(2. * v);
    }
    centres.push_back({u, v});
  }
  for (const auto &c : centres) {
    for (int d = 0; d < 8; ++d) {
      cases.push_back({&I, c.first, c.second, d, name});
    }
  }
}

vpImage<unsigned char> noise(int width, int height, long seed)
{
  vpImage<unsigned char> I(static_cast<unsigned int>(height), static_cast<unsigned int>(width));
  vpUniRand rand(seed);
  for (unsigned int k = 0; k < I.getSize(); ++k) {
    I.bitmap[k] = static_cast<unsigned char>(rand.uniform(0, 256));
  }
  return I;
}

vpImage<unsigned char> renderedTarget()
{
  vpImage<unsigned char> I;
  vpSSLRenderer renderer(vpCameraParameters(600., 600., 319.5, 239.5), 640, 480);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.render(vpHomogeneousMatrix(0.02, -0.01, 1.0, vpMath::rad(10.), vpMath::rad(-8.), vpMath::rad(5.)), I);
  return I;
}

vpImage<unsigned char> photograph()
{
  vpImage<unsigned char> I;
  vpImageIo::read(I, std::string(VISP_SSL_IMAGES_DIR) + "/AprilTag/AprilTag.pgm");
  return I;
}

// The reference ring test's integral of the profile from 0 to rho, linear between samples.
double referenceIntegral(const std::vector<float> &P, const std::vector<double> &C, double step, double rho)
{
  const size_t lastC = C.size() - 1, nbP = P.size();
  const double k = rho * (1. / step);
  const size_t i = std::min(static_cast<size_t>(k), lastC);
  const double f = k - static_cast<double>(i);
  if (i + 1 >= nbP) {
    return C[i];
  }
  const double pr = P[i] + 0.5 * f * (P[i + 1] - P[i]);
  return C[i] + f * step * pr;
}

// The reference ring test's first two ring pairs, in plain scalar code: whether
// the radius R goes on past them.
bool referenceSurvives(const std::vector<float> &P, const std::vector<double> &C, double step, double q,
                       double minWidth, double minRadius, double R)
{
  auto integral = [&](double rho) { return referenceIntegral(P, C, step, rho); };
  double outerEdge = R, outerIntegral = integral(R), previous = 0., cmax = 0.;
  for (int k = 0; k < 3; ++k) {
    const double innerEdge = outerEdge * q;
    if (outerEdge - innerEdge < minWidth || innerEdge < minRadius) {
      return false;
    }
    const double innerIntegral = integral(innerEdge);
    const double mean = (outerIntegral - innerIntegral) / (outerEdge - innerEdge);
    if (k == 1) {
      const double c0 = mean - previous;
      if (c0 < 3.5) {
        return false;
      }
      cmax = std::max(cmax, c0);
    } else if (k == 2) {
      const double c1 = previous - mean;
      cmax = std::max(cmax, c1);
      if (c1 < 0.25 * cmax) {
        return false;
      }
    }
    outerIntegral = innerIntegral;
    previous = mean;
    outerEdge = innerEdge;
  }
  return true;
}

// The reference ring test and the tests rayCandidates() runs on its result, in plain scalar code (solidRings()
// aside): whether the radius R passes them, and its score.
bool referenceScore(const std::vector<float> &P, const std::vector<double> &C, double step, double q, double minWidth,
                    double minRadius, double clearWidth, double R, double &score)
{
  auto integral = [&](double rho) { return referenceIntegral(P, C, step, rho); };
  double contrast[64], level[65];
  int nb = 0;
  double previous = 0., outerEdge = R, cmax = 0.;
  double outerIntegral = integral(outerEdge);
  for (int k = 0; nb < 64; ++k) {
    const double innerEdge = outerEdge * q;
    if (outerEdge - innerEdge < minWidth || innerEdge < minRadius) {
      break;
    }
    const double innerIntegral = integral(innerEdge);
    const double mean = (outerIntegral - innerIntegral) / (outerEdge - innerEdge);
    outerIntegral = innerIntegral;
    level[k] = mean;
    if (k > 0) {
      contrast[nb] = ((k - 1) % 2 == 0) ? mean - previous : previous - mean;
      cmax = std::max(cmax, contrast[nb]);
      ++nb;
      if ((nb == 1 && contrast[0] < 3.5) || (nb == 2 && contrast[1] < 0.25 * cmax)) {
        return false;
      }
    }
    previous = mean;
    outerEdge = innerEdge;
  }
  int nbExpected = 0, nbPairs = 0;
  for (double r = R * q; nbExpected < nb && r * (1. - q) >= clearWidth; r *= q) {
    ++nbExpected;
  }
  score = 0.;
  for (int i = 0; i < nb; ++i) {
    if (contrast[i] >= 0.25 * cmax) {
      score += contrast[i];
      ++nbPairs;
    } else if (contrast[i] <= -0.15 * cmax) {
      return false;
    } else {
      break;
    }
  }
  if (nbPairs < 2) {
    return false;
  }
  double black = 0., white = 0.;
  int nbBlack = 0, nbWhite = 0;
  const int nbLevels = std::min(nbPairs, std::max(2, nbExpected));
  for (int k = 1; k <= nbLevels; ++k) {
    if (k % 2 == 0) {
      black += level[k];
      ++nbBlack;
    } else {
      white += level[k];
      ++nbWhite;
    }
  }
  black /= nbBlack;
  white /= nbWhite;
  const double darkTolerance = (nbExpected >= 2 || nbPairs < 3) ? 0.3 : 0.6;
  if (level[0] - black > 0.3 * (white - black) || black - level[0] > darkTolerance * (white - black)) {
    return false;
  }
  if (nbPairs < std::max(2, std::min(nbExpected - 1, 3))) {
    return false;
  }
  return !(score < 6. * nbPairs || contrast[0] < 0.6 * score / nbPairs);
}

struct ScreenCase
{
  std::vector<float> P;
  std::vector<double> C;
  std::vector<double> radii;
  double minWidth, minRadius, clearWidth;
  std::string name;
};

// A case from a profile: its running integral as ray() computes it, and the radius grid of ratio 1.02 from 4 px to
// past its last sample (radii beyond the profile read its last integral).
ScreenCase screenCase(const std::vector<float> &P, double pixelScale, const std::string &name)
{
  ScreenCase c;
  c.P = P;
  c.C.assign(P.size(), 0.);
  const double step = 0.5, halfStep = 0.5 * step;
  double integral = 0.;
  for (size_t i = 1; i < P.size(); ++i) {
    integral = integral + halfStep * (P[i - 1] + P[i]);
    c.C[i] = integral;
  }
  for (double r = 4. * pixelScale; r <= 1.1 * step * P.size(); r *= 1.02) {
    c.radii.push_back(r);
  }
  c.minWidth = 0.8 * pixelScale;
  c.minRadius = 1.0 * pixelScale;
  c.clearWidth = 2.5 * pixelScale;
  c.name = name;
  EXPECT_GE(c.radii.size(), 4u) << name;
  return c;
}

int checkScreen(const std::vector<ScreenCase> &cases, const char *target, size_t &survivors, size_t &total,
                size_t &read)
{
  int failures = 0;
  const double q = std::sqrt(0.5);
  std::vector<uint32_t> got;
  for (const ScreenCase &c : cases) {
    std::vector<uint32_t> expected;
    for (size_t i = 0; i < c.radii.size(); ++i) {
      if (referenceSurvives(c.P, c.C, 0.5, q, c.minWidth, c.minRadius, c.radii[i])) {
        expected.push_back(static_cast<uint32_t>(i));
      }
    }
    // Every length of the grid, so that each lane count of the last vector is met.
    for (size_t n : {c.radii.size(), c.radii.size() - 1, c.radii.size() / 2 + 1, size_t(1), size_t(3)}) {
      const vpSSLRayKernel::Profile profile = {c.P.data(), c.C.data(), c.P.size(),  0.5, 2.,
                                               q,          c.minWidth, c.minRadius, 3.5};
      got.assign(n + 1, 0xFFFFFFFFu);
      const size_t nb = vpSSLRayKernel::screen(profile, c.radii.data(), n, got.data());
      std::vector<uint32_t> want;
      for (uint32_t i : expected) {
        if (i < n) {
          want.push_back(i);
        }
      }
      got.resize(nb);
      if (got != want) {
        ADD_FAILURE() << target << ", " << c.name << ", " << n << " radii: " << nb << " survivors instead of "
                      << want.size();
        ++failures;
      }
      if (n == c.radii.size()) {
        survivors += want.size();
        total += n;
        // The survivors' whole reading.
        std::vector<uint32_t> passed(nb + 1, 0xFFFFFFFFu), expectedPassed;
        std::vector<double> scores(nb + 1, -1.), expectedScores;
        const vpSSLRayKernel::ScoreRules rules = {c.clearWidth, 6., 0.6, 3, 0.3, 0.6};
        const size_t nbPassed =
            vpSSLRayKernel::score(profile, rules, c.radii.data(), got.data(), nb, passed.data(), scores.data());
        for (uint32_t i : want) {
          double score = 0.;
          if (referenceScore(c.P, c.C, 0.5, q, c.minWidth, c.minRadius, c.clearWidth, c.radii[i], score)) {
            expectedPassed.push_back(i);
            expectedScores.push_back(score);
          }
        }
        passed.resize(nbPassed);
        scores.resize(nbPassed);
        bool sameScores = scores.size() == expectedScores.size();
        for (size_t k = 0; sameScores && k < scores.size(); ++k) {
          sameScores = std::memcmp(&scores[k], &expectedScores[k], sizeof(double)) == 0;
        }
        if (passed != expectedPassed || !sameScores) {
          ADD_FAILURE() << target << ", " << c.name << ": " << nbPassed << " radii read as rings instead of "
                        << expectedPassed.size() << (sameScores ? "" : ", or other scores");
          ++failures;
        }
        read += expectedPassed.size();
      }
    }
  }
  return failures;
}

void addProfiles(std::vector<ScreenCase> &cases, const vpImage<unsigned char> &I, double u, double v,
                 const std::string &name)
{
  for (int d = 0; d < 8; ++d) {
    const size_t n = raySamples(I, u, v, d, 0.5);
    std::vector<float> P(n);
    for (size_t i = 0; i < n; ++i) {
      P[i] = referenceSample(I, u, v, d, 0.5, i);
    }
    if (n >= 20) {
      cases.push_back(screenCase(P, 1., name + ", ray " + std::to_string(d)));
    }
  }
}
} // namespace

TEST(RingKernels, RaySamplesAreTheScalarOnesOnEveryTarget)
{
  // Odd sizes and a single row or column; every ray from the corners and the middle reaches a border, and those
  // going right and down reach the last column, row and pixel.
  const vpImage<unsigned char> grey = noise(97, 83, 1), row = noise(61, 1, 2), column = noise(1, 45, 3),
                               tiny = noise(2, 2, 4);
  const vpImage<unsigned char> rendered = renderedTarget(), photo = photograph();
  std::vector<RayCase> cases;
  addRays(cases, grey, "noise 97x83", 30, 5);
  addRays(cases, row, "one row", 5, 6);
  addRays(cases, column, "one column", 5, 7);
  addRays(cases, tiny, "2x2", 3, 8);
  addRays(cases, rendered, "rendered", 20, 9);
  addRays(cases, photo, "AprilTag.pgm", 20, 10);
  EXPECT_EQ(onEveryTarget([&](const char *t) { return checkSamples(cases, t); }), 0);
}

TEST(RingKernels, ScreenedAndScoredRadiiAreThoseOfRayScoreOnEveryTarget)
{
  std::vector<ScreenCase> cases;
  vpUniRand rand(11);
  // Noise (few survivors), few grey levels (ties of the ring means), and square waves of the printed ratio whose
  // ring edges fall on the grid or between its radii (many survivors, at the landmark's radius and its copies).
  for (int k = 0; k < 20; ++k) {
    std::vector<float> P(static_cast<size_t>(rand.uniform(20, 700)));
    for (float &p : P) {
      p = static_cast<float>(k % 2 == 0 ? rand.uniform(0., 255.) : 85 * rand.uniform(0, 4));
    }
    cases.push_back(screenCase(P, k % 4 == 3 ? 2. : 1., "noise " + std::to_string(k)));
  }
  for (int k = 0; k < 10; ++k) {
    const double R = rand.uniform(5., 300.), contrast = rand.uniform(2., 200.), background = rand.uniform(0., 255.);
    std::vector<float> P(static_cast<size_t>(2. * R * rand.uniform(0.9, 1.6)));
    for (size_t i = 0; i < P.size(); ++i) {
      const double rho = 0.5 * i, x = rho / R;
      const double level = x > 1. ? background : std::floor(2. * std::log(std::max(x, 1e-9)) / std::log(0.5));
      P[i] = static_cast<float>(x > 1. ? background : 128. + contrast * (std::fmod(level, 2.) == 0. ? -0.5 : 0.5));
    }
    cases.push_back(screenCase(P, 1., "rings of radius " + std::to_string(R)));
  }
  // Real rays: from the landmarks' centres of a rendered ssl3-a3 and from points of a photograph.
  const vpImage<unsigned char> rendered = renderedTarget(), photo = photograph();
  vpSSLRenderer renderer(vpCameraParameters(600., 600., 319.5, 239.5), 640, 480);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  const vpHomogeneousMatrix cMo(0.02, -0.01, 1.0, vpMath::rad(10.), vpMath::rad(-8.), vpMath::rad(5.));
  for (const vpImagePoint &c : renderer.projectLandmarks(cMo)) {
    addProfiles(cases, rendered, c.get_u() + 0.3, c.get_v() - 0.2, "rendered landmark");
  }
  for (int k = 0; k < 6; ++k) {
    addProfiles(cases, photo, rand.uniform(0., 639.), rand.uniform(0., 479.), "AprilTag.pgm");
  }
  size_t survivors = 0, total = 0, read = 0;
  EXPECT_EQ(onEveryTarget([&](const char *t) { return checkScreen(cases, t, survivors, total, read); }), 0);
  // The comparison tells radii apart: some survive the screen, most do not, and some of those are read as rings.
  EXPECT_GT(survivors, total / 50);
  EXPECT_LT(survivors, total / 2);
  EXPECT_GT(read, 0u);
  EXPECT_LT(read, survivors / 2);
}

TEST(RingKernels, LocalMaximaAreTheScalarOnesOnEveryTarget)
{
  // Maps of few values (plateaus and ties everywhere) and of many; rows with and without neighbours.
  vpUniRand rand(12);
  const int W = 131, H = 7;
  std::vector<std::vector<int>> maps;
  for (int levels : {2, 3, 1000}) {
    std::vector<int> M(static_cast<size_t>(W * H));
    for (int &m : M) {
      m = rand.uniform(0, levels);
    }
    maps.push_back(M);
  }
  int found = 0;
  const int failures = onEveryTarget([&](const char *target) {
    int bad = 0;
    std::vector<int> got(W);
    for (const std::vector<int> &M : maps) {
      for (int v = 0; v < H; ++v) {
        const int *above = v > 0 ? &M[(v - 1) * W] : nullptr, *row = &M[v * W];
        const int *below = v + 1 < H ? &M[(v + 1) * W] : nullptr;
        for (int threshold : {0, 1, 2, 500}) {
          for (int u0 : {1, 2, 17}) {
            for (int u1 : {W - 2, W - 3, 40, u0}) {
              std::vector<int> expected;
              for (int u = u0; u <= u1; ++u) {
                const int m = row[u];
                bool isMax = m >= threshold && row[u - 1] <= m && row[u + 1] < m;
                for (int du = -1; du <= 1 && isMax; ++du) {
                  isMax = (above == nullptr || above[u + du] <= m) && (below == nullptr || below[u + du] < m);
                }
                if (isMax) {
                  expected.push_back(u);
                }
              }
              const int nb = vpSSLPeakKernel::localMaxima(above, row, below, u0, u1, threshold, got.data());
              found += nb;
              if (std::vector<int>(got.begin(), got.begin() + nb) != expected) {
                ADD_FAILURE() << target << ", row " << v << ", columns " << u0 << "-" << u1 << ", threshold "
                              << threshold << ": " << nb << " maxima instead of " << expected.size();
                ++bad;
              }
            }
          }
        }
      }
    }
    return bad;
  });
  EXPECT_EQ(failures, 0);
  EXPECT_GT(found, 0);
}
