/*
  vpSSLConcentricReader reads a landmark from the whole of its rings: on views of the independent corpus
  (visp_ssl_bench, no code shared with vpSSLRenderer) it finds the centre and the outer ellipse of oblique and
  blurred landmarks, and it reads nothing on a lone disc, a bull's-eye of equal rings or a chessboard.
*/
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include <visp3/core/vpImageFilter.h>
#include <visp3/ssl/vpSSLConcentricReader.h>
#include <visp3/ssl_bench/vpSSLCorpusPhotos.h>
#include <visp3/ssl_bench/vpSSLCorpusSheet.h>
#include <visp3/ssl_bench/vpSSLCorpusView.h>

#include "common/ssl_test_corpus_view.h"

namespace {
// A view without water loss, vignetting or noise (each case adds what it tests), the sheet on dark water.
vpSSLCorpusViewParams view(double tilt, double depth, double sigma)
{
  vpSSLCorpusViewParams p;
  p.camera.px = p.camera.py = 800.;
  p.camera.u0 = 319.3;
  p.camera.v0 = 241.7;
  p.background = vpSSLCorpusViewParams::DARK_WATER;
  for (int c = 0; c < 3; ++c) {
    p.attenuation[c] = 0.;
    p.backscatter[c] = 0.;
  }
  p.spot = 0.;
  p.vignetting = 0.;
  p.gaussSigma = sigma;
  p.noiseGain = 0.;
  p.readNoise = 0.002;
  p.gamma = 1.;
  // Rotation about the target's X axis by tilt, B's centre on the optical axis at depth.
  const double c = std::cos(tilt), s = std::sin(tilt), bx = vpSSLTarget::ssl3a3().getLandmark(0).x;
  vpHomogeneousMatrix M;
  M[1][1] = c;
  M[1][2] = -s;
  M[2][1] = s;
  M[2][2] = c;
  M[0][3] = -bx;
  M[2][3] = depth;
  p.cMo = M;
  return p;
}

const vpSSLCorpusSheet &sheet()
{
  static const vpSSLCorpusSheet s = vpSSLCorpusSheet::sslTarget(vpSSLTarget::ssl3a3());
  return s;
}

// B of ssl3-a3 rendered by the independent corpus, turned by tilt (deg) about the sheet's X axis, at depth (m),
// blurred by sigma (px).
vpSSLCorpusView renderB(double tilt, double depth, double sigma)
{
  vpSSLCorpusView v(vpSSLTarget::ssl3a3());
  vpSSLCorpusPhotos none;
  v.render(view(vpMath::rad(tilt), depth, sigma), &sheet(), none);
  return v;
}

// Calls f(view, B's truth, blur sigma) on B of 25 to 100 px (depth 3.2 to 0.8 m) seen face-on to 60 degrees off its
// normal, sharp to blurred by 2 px.
template <typename F> void forEachB(F f)
{
  for (double tilt : {0., 30., 45., 60.}) {
    for (double depth : {0.8, 1.6, 3.2}) {
      for (double sigma : {0., 1., 2.}) {
        const vpSSLCorpusView v = renderB(tilt, depth, sigma);
        f(v, v.getTruth()[0], sigma);
      }
    }
  }
}

vpSSLConcentricReader reader()
{
  vpSSLConcentricReader r;
  r.setP(0.5);
  r.setRadiusRange(4., 300.);
  return r;
}

// The shapes of ReadsNothingOnDiscsBullseyesAndChessboards, centred on (100, 100) in 201 x 201 px: kind 0 a dark disc
// of radius size, 1 a light disc on a dark ground, 2 rings of equal width size / 2, the outer one dark, 3 a chessboard
// of squares of side size with a corner at the centre; dark grey level dark on 220, blurred by sigma (px), plus
// uniform noise of +-2 grey levels from the linear congruential generator's state.
vpImage<unsigned char> noisyShape(int kind, double size, double sigma, double dark, unsigned int &state)
{
  const int N = 201, c = 100;
  auto noise = [&]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / (1u << 24) - 0.5; // uniform in [-0.5, 0.5)
  };
  vpImage<double> D(N, N);
  for (int v = 0; v < N; ++v) {
    for (int u = 0; u < N; ++u) {
      const double rho = std::hypot(u - c, v - c);
      bool isDark = false;
      switch (kind) {
      case 0:
        isDark = rho < size;
        break;
      case 1:
        isDark = rho >= size;
        break;
      case 2:
        isDark = rho < 5 * size / 2. && static_cast<int>(rho / (size / 2.)) % 2 == 0;
        break;
      default:
        isDark =
            ((static_cast<int>(std::floor((u - c) / size)) + static_cast<int>(std::floor((v - c) / size))) & 1) != 0;
      }
      D[v][u] = isDark ? dark : 220.;
    }
  }
  vpImage<double> B = D;
  if (sigma > 0.) {
    vpImageFilter::gaussianBlur(D, B, 2 * static_cast<unsigned int>(std::ceil(3. * sigma)) + 1, sigma);
  }
  vpImage<unsigned char> I(N, N);
  for (unsigned int i = 0; i < I.getSize(); ++i) {
    I.bitmap[i] = static_cast<unsigned char>(std::min(255., std::max(0., B.bitmap[i] + 4. * noise() + 0.5)));
  }
  return I;
}
} // namespace

TEST(ConcentricReader, ReadsObliqueAndBlurredLandmarks)
{
  // doc/detector.md: from a start 2 px off, B of 25 to 100 px seen face-on to 60 degrees off its normal. Up to 1 px
  // of blur: the centre within 0.8 % of the radius (0.3 px at least) of the projection of the landmark's centre, the
  // major semi-axis within 2 %, the minor one within 3.5 %. With 2 px of blur: 1.5 % (0.7 px), 2 % and 7 %. B of
  // 50 px and more: the centre within 0.15 px up to 1 px of blur, 0.45 px with 2 px.
  vpSSLConcentricReader r = reader();
  forEachB([&](const vpSSLCorpusView &v, const vpSSLCorpusLandmarkTruth &B, double sigma) {
    vpSSLLandmark l;
    l.u = B.u + 1.6;
    l.v = B.v - 1.2;
    const std::string what = "view angle " + std::to_string(B.viewAngle) + " sigma " + std::to_string(sigma) + " B " +
                             std::to_string(B.a) + " px";
    ASSERT_TRUE(r.read(v.getImage(), l)) << what << ", stage " << r.getStage();
    const double centre = std::hypot(l.u - B.u, l.v - B.v);
    if (B.a >= 45.) {
      // B of 50 px and more: the centre from the disc inside the third ring.
      EXPECT_LT(centre, sigma <= 1. ? 0.15 : 0.45) << what;
    }
    if (sigma <= 1.) {
      EXPECT_LT(centre, std::max(0.3, 0.008 * B.a)) << what;
      EXPECT_NEAR(l.radius / B.a, 1., 0.02) << what;
      EXPECT_NEAR(l.minorRadius / B.b, 1., 0.035) << what;
    } else {
      EXPECT_LT(centre, std::max(0.7, 0.015 * B.a)) << what;
      EXPECT_NEAR(l.radius / B.a, 1., 0.02) << what;
      EXPECT_NEAR(l.minorRadius / B.b, 1., 0.07) << what;
    }
  });
}

TEST(ConcentricReader, ReportsTheScaleAtWhichTheRingsFollowTheWave)
{
  // The similarity read() reports (and compares with 0.5) is that of the landmark it reports: on B of 50 and
  // 100 px, similarity() at the ellipse read gives it again within 0.02 (up to 0.018 here, from the different
  // binning of the same profile; 0.028 if read() correlated the wave ending at the phase's R rather than at the R
  // the printed edges give). On B of 25 px the binning alone moves it by up to 0.05.
  vpSSLConcentricReader r = reader();
  double worst = 0.;
  forEachB([&](const vpSSLCorpusView &v, const vpSSLCorpusLandmarkTruth &B, double sigma) {
    if (B.a < 45.) {
      return;
    }
    vpSSLLandmark l;
    l.u = B.u + 1.6;
    l.v = B.v - 1.2;
    ASSERT_TRUE(r.read(v.getImage(), l));
    const double reported = r.getSimilarity();
    const double atRead = r.similarity(v.getImage(), l);
    worst = std::max(worst, std::fabs(reported - atRead));
    EXPECT_NEAR(reported, atRead, 0.02) << "view angle " << B.viewAngle << " sigma " << sigma << " B " << B.a << " px";
  });
  std::cout << "largest difference " << worst << std::endl;
}

TEST(ConcentricReader, ReadsNothingOnDiscsBullseyesAndChessboards)
{
  vpSSLConcentricReader r = reader();
  const int N = 201, c = 100;
  for (int kind = 0; kind < 4; ++kind) {
    for (double size : {6., 9., 14., 22., 35.}) {
      vpImage<unsigned char> I(N, N);
      for (int v = 0; v < N; ++v) {
        for (int u = 0; u < N; ++u) {
          const double rho = std::hypot(u - c, v - c);
          bool dark = false;
          switch (kind) {
          case 0: // a dark disc
            dark = rho < size;
            break;
          case 1: // a light disc on a dark ground
            dark = rho >= size;
            break;
          case 2: // rings of equal width, the outer one dark
            dark = rho < 5 * size / 2. && static_cast<int>(rho / (size / 2.)) % 2 == 0;
            break;
          default: // a chessboard with a corner at the centre
            dark = ((static_cast<int>(std::floor((u - c) / size)) + static_cast<int>(std::floor((v - c) / size))) &
                    1) != 0;
          }
          I[v][u] = dark ? 30 : 220;
        }
      }
      vpSSLLandmark l;
      l.u = c + 0.7;
      l.v = c - 0.4;
      EXPECT_FALSE(r.read(I, l)) << "kind " << kind << " size " << size << ": read R " << l.radius;
    }
  }
}

TEST(ConcentricReader, SimilaritySeparatesLandmarksFromEqualRings)
{
  // vpSSLDetector keeps a landmark whose ring profile correlates with s_p at 0.5 or more (doc/detector.md): B of 25
  // to 100 px at its true ellipse, face-on to 60 degrees and blurred up to 2 px, reaches it (0.54 at 25 px, 60
  // degrees and 2 px of blur); a bull's-eye of four to six equal rings read at its outer edge does not.
  vpSSLConcentricReader r = reader();
  double lowest = 1.;
  forEachB([&](const vpSSLCorpusView &v, const vpSSLCorpusLandmarkTruth &B, double) {
    lowest = std::min(lowest, r.similarity(v.getImage(), trueEllipse(B)));
  });
  EXPECT_GE(lowest, 0.5);
  double highest = -1.;
  const int N = 201, c = 100;
  for (int rings : {4, 5, 6}) {
    for (double outer : {24., 32., 45., 60., 90.}) {
      const double width = outer / rings;
      vpImage<unsigned char> I(N, N);
      for (int v = 0; v < N; ++v) {
        for (int u = 0; u < N; ++u) {
          const double rho = std::hypot(u - c, v - c);
          // The outermost ring dark, as a landmark's.
          const bool dark = rho < outer && static_cast<int>((outer - rho) / width) % 2 == 0;
          I[v][u] = dark ? 30 : 220;
        }
      }
      vpSSLLandmark l;
      l.u = c;
      l.v = c;
      l.radius = l.minorRadius = outer;
      const double s = r.similarity(I, l);
      highest = std::max(highest, s);
    }
  }
  EXPECT_LT(highest, 0.5);
}

TEST(ConcentricReader, EqualRingsTellBlurredBullsEyesApart)
{
  // doc/detector.md: a bull's-eye of equal rings blurred by 1.5 to 2 px, read at an outer edge of 15 px, correlates
  // with s_p at 0.5 or more; isEqualRings() flags every such reading of 15 px and more, and no B of the grid of
  // corpus views (25 to 100 px, face-on to 60 degrees, up to 2 px of blur) at its true ellipse.
  vpSSLConcentricReader r = reader();
  forEachB([&](const vpSSLCorpusView &v, const vpSSLCorpusLandmarkTruth &B, double sigma) {
    r.similarity(v.getImage(), trueEllipse(B));
    EXPECT_FALSE(r.isEqualRings()) << "B " << B.a << " px, view angle " << B.viewAngle << ", sigma " << sigma;
  });
  // Bull's-eyes of 6 to 10 rings of 3 to 7 px, the centre dark, supersampled 4 x 4 and blurred.
  const int N = 241, c = 120, k = 4;
  int passing = 0;
  for (int rings : {6, 8, 10}) {
    for (double width : {3., 4., 5., 7.}) {
      for (double sigma : {0., 1., 1.5, 2.}) {
        vpImage<unsigned char> I(N, N);
        for (int v = 0; v < N; ++v) {
          for (int u = 0; u < N; ++u) {
            double sum = 0.;
            for (int j = 0; j < k * k; ++j) {
              const double rho = std::hypot(u + (j % k + 0.5) / k - 0.5 - c, v + (j / k + 0.5) / k - 0.5 - c);
              const int ring = static_cast<int>(rho / width);
              sum += ring < rings && ring % 2 == 0 ? 30. : 200.;
            }
            I[v][u] = static_cast<unsigned char>(sum / (k * k) + 0.5);
          }
        }
        if (sigma > 0.) {
          vpImage<double> F;
          vpImageFilter::gaussianBlur(I, F, 2 * static_cast<unsigned int>(3. * sigma) + 1, sigma);
          for (int v = 0; v < N; ++v) {
            for (int u = 0; u < N; ++u) {
              I[v][u] = static_cast<unsigned char>(F[v][u] + 0.5);
            }
          }
        }
        // Read at the outer edge of each dark ring, as the rays read a bull's-eye whose outer rings match s_p.
        for (int outer = 1; outer < rings; outer += 2) {
          vpSSLLandmark l;
          l.u = c;
          l.v = c;
          l.radius = l.minorRadius = outer * width;
          if (l.radius >= 15. && r.similarity(I, l) >= 0.5) {
            ++passing;
            EXPECT_TRUE(r.isEqualRings())
                << rings << " rings of " << width << " px, sigma " << sigma << ", read at " << l.radius << " px";
          }
        }
      }
    }
  }
  EXPECT_GE(passing, 5);
}

TEST(ConcentricReader, BlurredRingModelReadsFaintBlurredLandmarks)
{
  // doc/detector.md: B of 12 to 20 px on sand, ink of albedo 0.8 on paper of 0.85 (15 noise sigmas of contrast),
  // blurred by 1.5 to 2 px, face-on and 40 degrees off its normal: the outer-ring tests read no ring, the
  // blurred-ring model reads each within 10 % of its radius, its centre within 0.15 of it.
  vpSSLConcentricReader off = reader(), on = reader();
  on.setBlurredRingModel(true);
  EXPECT_FALSE(off.getBlurredRingModel());
  const double cases[4][3] = {{0., 5.3, 2.}, {0., 6.5, 1.5}, {40., 4., 2.}, {40., 6.5, 1.5}}; // tilt, depth, sigma
  for (const auto &c : cases) {
    vpSSLCorpusViewParams p = view(vpMath::rad(c[0]), c[1], c[2]);
    p.background = vpSSLCorpusViewParams::SAND;
    p.ink = 0.8;
    p.readNoise = 0.004;
    vpSSLCorpusView v(vpSSLTarget::ssl3a3());
    vpSSLCorpusPhotos none;
    v.render(p, &sheet(), none);
    const vpSSLCorpusLandmarkTruth &B = v.getTruth()[0];
    const std::string what =
        "tilt " + std::to_string(c[0]) + " B " + std::to_string(B.a) + " px, sigma " + std::to_string(c[2]);
    vpSSLLandmark a, b;
    a.u = b.u = B.u + 0.8;
    a.v = b.v = B.v - 0.6;
    EXPECT_FALSE(off.read(v.getImage(), a)) << what << ": read R " << a.radius;
    ASSERT_TRUE(on.read(v.getImage(), b)) << what << ", stage " << on.getStage();
    EXPECT_NEAR(b.radius / B.a, 1., 0.1) << what;
    EXPECT_LT(std::hypot(b.u - B.u, b.v - B.v), 0.15 * B.a) << what;
    EXPECT_GE(on.getSimilarity(), 0.945) << what;
  }
}

TEST(ConcentricReader, BlurredRingModelAddsNoReadingOnDiscsBullseyesAndChessboards)
{
  // The shapes of ReadsNothingOnDiscsBullseyesAndChessboards, sharp and blurred by 1.5 and 2.5 px, at full and at a
  // tenth of the contrast, with noise: the blurred-ring model reads none that the outer-ring tests do not (they read a
  // few bull's-eyes of rings 3 to 4.5 px wide among them, as they read every blurred bull's-eye whose outer rings
  // follow s_p, doc/detector.md).
  vpSSLConcentricReader r = reader(), off = reader();
  r.setBlurredRingModel(true);
  const int c = 100;
  unsigned int state = 12345u;
  for (int kind = 0; kind < 4; ++kind) {
    for (double size : {6., 9., 14., 22., 35.}) {
      for (double sigma : {0., 1.5, 2.5}) {
        for (double dark : {30., 200.}) {
          const vpImage<unsigned char> I = noisyShape(kind, size, sigma, dark, state);
          vpSSLLandmark l, k;
          l.u = k.u = c + 0.7;
          l.v = k.v = c - 0.4;
          const bool read = r.read(I, l), readOff = off.read(I, k);
          EXPECT_TRUE(!read || readOff) << "kind " << kind << " size " << size << " sigma " << sigma << " dark " << dark
                                        << ": read R " << l.radius;
        }
      }
    }
  }
}

TEST(ConcentricReader, ReadAtReadsBlurredLandmarksOfAKnownShape)
{
  // B of 15 px on sand, ink of albedo 0.8 on paper of 0.85, blurred by 2.5 px, face-on and 40 degrees off its
  // normal: read() finds no ring (the fit does not lock, or no copy passes), readAt() about an ellipse 10 % too large,
  // from 1 px off the centre, reads each within 10 % of its radius, its centre within 0.15 of it.
  vpSSLConcentricReader r = reader();
  r.setBlurredRingModel(true);
  for (double tilt : {0., 40.}) {
    vpSSLCorpusViewParams p = view(vpMath::rad(tilt), 5.3, 2.5);
    p.background = vpSSLCorpusViewParams::SAND;
    p.ink = 0.8;
    p.readNoise = 0.004;
    vpSSLCorpusView v(vpSSLTarget::ssl3a3());
    vpSSLCorpusPhotos none;
    v.render(p, &sheet(), none);
    const vpSSLCorpusLandmarkTruth &B = v.getTruth()[0];
    const std::string what = "tilt " + std::to_string(tilt) + " B " + std::to_string(B.a) + " px";
    vpSSLLandmark a, b = trueEllipse(B);
    a.u = b.u = B.u + 0.8;
    a.v = b.v = B.v - 0.6;
    b.radius *= 1.1;
    b.minorRadius *= 1.1;
    EXPECT_FALSE(r.read(v.getImage(), a)) << what << ": read R " << a.radius;
    ASSERT_TRUE(r.readAt(v.getImage(), b)) << what << ", stage " << r.getStage();
    EXPECT_NEAR(b.radius / B.a, 1., 0.1) << what;
    EXPECT_LT(std::hypot(b.u - B.u, b.v - B.v), 0.15 * B.a) << what;
  }
}

TEST(ConcentricReader, ReadAtReadsNothingOnDiscsOrChessboards)
{
  // The shapes of ReadsNothingOnDiscsBullseyesAndChessboards, sharp and blurred by 1.5 and 2.5 px, at full and at a
  // tenth of the contrast, with noise, read about the circle of their outer edge (the chessboard's square) and one
  // 20 % larger: readAt() reads no disc and no chessboard, and no bull's-eye that read() does not.
  vpSSLConcentricReader r = reader();
  r.setBlurredRingModel(true);
  const int c = 100;
  unsigned int state = 54321u;
  for (int kind = 0; kind < 4; ++kind) {
    for (double size : {6., 9., 14., 22., 35.}) {
      for (double sigma : {0., 1.5, 2.5}) {
        for (double dark : {30., 200.}) {
          const vpImage<unsigned char> I = noisyShape(kind, size, sigma, dark, state);
          const double outer = kind == 2 ? 2.5 * size : size;
          for (double scale : {1., 1.2}) {
            vpSSLLandmark l, k;
            l.u = k.u = c + 0.7;
            l.v = k.v = c - 0.4;
            l.radius = l.minorRadius = scale * outer;
            bool read = r.readAt(I, l);
            if (read) {
              r.similarity(I, l);
              read = !r.isEqualRings();
            }
            const bool readFree = kind == 2 && r.read(I, k);
            EXPECT_TRUE(!read || readFree) << "kind " << kind << " size " << size << " sigma " << sigma << " dark "
                                           << dark << " scale " << scale << ": read R " << l.radius;
          }
        }
      }
    }
  }
}
