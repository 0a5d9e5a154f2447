/*
  vpSSLCentreTone::measure(), the tests by which the detector turns away round clutter of 10 to 40 px whose outer rings
  pass for a landmark's: on the landmarks of ssl3-a3 rendered by the independent corpus (visp_ssl_bench, no code
  shared with vpSSLRenderer), 10 to 40 px, face-on to 60 degrees off the normal, sharp to blurred by 2.5 px, the centre
  disc's level lies 2 / 3 of the way from the outer black ring's to the white ring's when sharp and face-on (the
  disc's white area), and never below the black ring's (the detector's bound, 0) where the detector reads the
  landmark at all: only where blur has washed the rings out (a minor semi-axis under 4 blur sigmas) does it fall
  below, and there the detector, even without its bull's-eye checks, reads nothing. The rise (the band about the edge
  at p^2 R over the core) stays under 0.8 on the same grid, below the detector's bound of 1. A drawn dark disc ringed
  in white and grey has its tone below 0, a drawn bull's-eye of five rings of one width ending in a dark dot its rise
  over 1; nothing is measured where the rings leave the image or have one level.
*/

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include <visp3/core/vpGaussRand.h>
#include <visp3/core/vpImageFilter.h>
#include <visp3/core/vpMath.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLLandmark.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_bench/vpSSLCorpusPhotos.h>
#include <visp3/ssl_bench/vpSSLCorpusSheet.h>
#include <visp3/ssl_bench/vpSSLCorpusView.h>

#include "../modules/ssl/src/vpSSLCentreTone.h"
#include "common/ssl_test_corpus_view.h"

namespace {
// A clean view (ssl_test_corpus_view.h) with a little read noise, landmark k's centre on the optical axis at depth (m),
// the sheet turned by tilt (rad) about its X axis, blurred by sigma (px). A small image, so that the sheet fills more
// than the 1 % of it above the 99th percentile that sets the exposure.
vpSSLCorpusViewParams view(size_t k, double tilt, double depth, double sigma)
{
  vpSSLCorpusViewParams p = cleanView();
  p.camera.width = 200;
  p.camera.height = 150;
  p.camera.u0 = 99.3;
  p.camera.v0 = 74.7;
  p.gaussSigma = sigma;
  p.readNoise = 0.002;
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  p.cMo = tiltedOnAxis(tilt, depth, target.getLandmark(k).x, target.getLandmark(k).y);
  return p;
}

// A round pattern of radius R (px) centred in a square image of side 2 R + 1 + 40 px: level(rho) at the relative radius
// rho < 1, the background outside, blurred by sigma (px; none at 0).
template <typename Level> vpImage<double> drawn(double R, double background, Level level, double sigma)
{
  const unsigned int side = static_cast<unsigned int>(2. * R) + 41;
  const double c = 0.5 * (side - 1);
  vpImage<double> D(side, side, background);
  for (unsigned int v = 0; v < side; ++v) {
    for (unsigned int u = 0; u < side; ++u) {
      const double rho = std::hypot(u - c, v - c) / R;
      if (rho < 1.) {
        D[v][u] = level(rho);
      }
    }
  }
  vpImage<double> B = D;
  if (sigma > 0.) {
    vpImageFilter::gaussianBlur(D, B, 7, sigma);
  }
  return B;
}

// D rounded to grey levels, with read noise from noise if given.
vpImage<unsigned char> grey(const vpImage<double> &D, vpGaussRand *noise = nullptr)
{
  vpImage<unsigned char> I(D.getHeight(), D.getWidth());
  for (unsigned int i = 0; i < I.getSize(); ++i) {
    const double g = D.bitmap[i] + (noise != nullptr ? (*noise)() : 0.) + 0.5;
    I.bitmap[i] = static_cast<unsigned char>(std::min(255., std::max(0., g)));
  }
  return I;
}

// The landmark measured: centred on the drawing of radius R.
vpSSLLandmark centredOn(const vpImage<double> &D, double R)
{
  vpSSLLandmark l;
  l.u = l.v = 0.5 * (D.getWidth() - 1);
  l.radius = l.minorRadius = R;
  return l;
}

} // namespace

TEST(CentreTone, NoLandmarkTheDetectorReadsIsDarkAtTheCentre)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet sheet = vpSSLCorpusSheet::sslTarget(target);
  vpSSLCorpusPhotos none;
  vpSSLCorpusView v(target);
  vpSSLDetector unchecked(target);
  unchecked.setEqualRingCheck(false);
  unchecked.setNbThreads(1);
  unsigned int measured = 0, washedOut = 0;
  double lowest = 1e9, highest = -1e9, highestRise = -1e9;
  for (size_t k = 0; k < target.size(); ++k) {
    for (double tilt : {0., 30., 45., 60.}) {
      for (double depth : {1., 1.5, 2.5, 4., 6., 8.}) {
        for (double sigma : {0., 1., 1.5, 2.5}) {
          v.render(view(k, vpMath::rad(tilt), depth, sigma), &sheet, none);
          const vpSSLCorpusLandmarkTruth &t = v.getTruth()[k];
          if (t.a < 10. || t.a >= 40.) {
            continue; // the radii the detector tests
          }
          const std::string what = t.name + " " + std::to_string(t.a) + " x " + std::to_string(t.b) + " px, tilt " +
                                   std::to_string(tilt) + ", sigma " + std::to_string(sigma);
          vpSSLCentreTone::Reading centre;
          if (!vpSSLCentreTone::measure(v.getImage(), trueEllipse(t), target.getP(), centre)) {
            // Two rings of one level: blur has left no ring to compare the centre with.
            EXPECT_LT(t.b, 4. * sigma) << what;
            ++washedOut;
            continue;
          }
          ++measured;
          const double tone = centre.tone;
          lowest = std::min(lowest, tone);
          highest = std::max(highest, tone);
          highestRise = std::max(highestRise, centre.rise);
          if (sigma == 0. && tilt == 0.) {
            EXPECT_NEAR(tone, 2. / 3., 0.1) << what;
          }
          // The detector's bound is 1; the corpus's landmarks reach 0.8 at most, and these must stay under it.
          EXPECT_LT(centre.rise, 0.8) << what;
          if (tone < 0.) {
            std::cout << "below 0: " << what << ": " << tone << std::endl;
            EXPECT_LT(t.b, 4. * sigma) << what;
            unchecked.detect(v.getImage());
            for (const vpSSLLandmark &l : unchecked.getLandmarks()) {
              EXPECT_GT(std::hypot(l.u - t.u, l.v - t.v), 0.15 * t.a) << what << ": read although dark at the centre";
            }
          }
        }
      }
    }
  }
  std::cout << measured << " landmarks measured: tone from " << lowest << " to " << highest << ", rise up to "
            << highestRise << "; " << washedOut << " with rings of one level" << std::endl;
  EXPECT_GE(measured, 150u);
  EXPECT_LE(washedOut, 5u);
}

TEST(CentreTone, DiscDarkerThanItsRingIsBelowZero)
{
  // A dark disc of 0.35 R ringed in white to 0.7 R, then grey to R (levels 30, 200, 90), sharp and blurred by 1 px: the
  // centre lies (30 - 90) / (200 - 90) = -0.55 of the way from the outer ring's level to the white ring's.
  const double R = 20.;
  for (double sigma : {0., 1.}) {
    const vpImage<double> D = drawn(
        R, 220., [](double rho) { return rho < 0.35  ? 30.
                                         : rho < 0.7 ? 200.
                                                     : 90.; }, sigma);
    const vpImage<unsigned char> I = grey(D);
    vpSSLLandmark l = centredOn(D, R);
    vpSSLCentreTone::Reading centre;
    ASSERT_TRUE(vpSSLCentreTone::measure(I, l, 0.5, centre)) << "sigma " << sigma;
    EXPECT_NEAR(centre.tone, -0.55, sigma == 0. ? 0.05 : 0.2) << "sigma " << sigma;
    // Its rings out of the image, or of one level: nothing measured.
    const double u = l.u;
    l.u = 5.;
    EXPECT_FALSE(vpSSLCentreTone::measure(I, l, 0.5, centre));
    vpImage<unsigned char> flat(I.getHeight(), I.getWidth(), 128);
    l.u = u;
    EXPECT_FALSE(vpSSLCentreTone::measure(flat, l, 0.5, centre));
  }
}

TEST(CentreTone, BullsEyeEndingInADarkDotRisesOverOne)
{
  // Five rings of one width, dark from 0.8 R to R, 0.4 R to 0.6 R and the dot inside 0.2 R (levels 60, 200, background
  // 220), sharp and blurred by 1 px. The core (to 0.106 R) is the dot, the band from 0.2 R to 0.3 R light, and the
  // "white ring" (0.53 R to 0.68 R) and "black ring" (0.74 R to 0.96 R) each straddle an edge, the white one the
  // lighter: the band lies above the core by about three times the rings' difference (printed), over the bound of 1,
  // while the tone is over 0, so the centre disc's level alone would not turn it away.
  const double R = 20.;
  for (double sigma : {0., 1.}) {
    const vpImage<double> D = drawn(
        R, 220., [](double rho) { return static_cast<int>(rho / 0.2) % 2 == 0 ? 60. : 200.; }, sigma);
    const vpImage<unsigned char> I = grey(D);
    const vpSSLLandmark l = centredOn(D, R);
    vpSSLCentreTone::Reading centre;
    ASSERT_TRUE(vpSSLCentreTone::measure(I, l, 0.5, centre)) << "sigma " << sigma;
    EXPECT_GT(centre.rise, 1.) << "sigma " << sigma;
    EXPECT_GT(centre.tone, 0.) << "sigma " << sigma;
    std::cout << "sigma " << sigma << ": rise " << centre.rise << ", tone " << centre.tone << std::endl;
  }
}

TEST(CentreTone, RiseErrorKeepsFaintLandmarksTheNoiseLiftsOverTheBound)
{
  // A faint landmark (p = 0.5, R = 14 px, rings 4 grey levels apart, blurred by 1 px) under read noise of 3 grey
  // levels, drawn 300 times with other noise. Its rise, about 0 without noise, spreads over the drawings; riseError,
  // the spread of the rise over eight sectors, is what the detector allows it beyond its bound of 1 (kMaxRise). The
  // sectors share the core's few pixels, so riseError understates that spread (between 0.3 and 1 of it), yet it halves
  // the drawings turned away at least.
  const double R = 14., p = 0.5;
  const vpImage<double> D = drawn(
      R, 110.,
      [p](double rho) {
        const int ring = rho > 0. ? static_cast<int>(std::floor(2. * std::log(rho) / std::log(p))) : 0;
        return ring % 2 == 0 ? 100. : 104.;
      },
      1.);
  vpGaussRand noise(3., 0., 7);
  const vpSSLLandmark l = centredOn(D, R);
  const int n = 3000;
  double s = 0., ss = 0., error = 0.;
  int measured = 0, overBound = 0, overBoundAndError = 0;
  for (int k = 0; k < n; ++k) {
    const vpImage<unsigned char> I = grey(D, &noise);
    vpSSLCentreTone::Reading centre;
    if (vpSSLCentreTone::measure(I, l, p, centre)) {
      s += centre.rise;
      ss += centre.rise * centre.rise;
      error += centre.riseError;
      ++measured;
      overBound += centre.rise > 1.;
      overBoundAndError += centre.rise > 1. + centre.riseError;
    }
  }
  ASSERT_GE(measured, n * 9 / 10);
  const double mean = s / measured, spread = std::sqrt((ss - s * s / measured) / (measured - 1));
  error /= measured;
  std::cout << "rise " << mean << " +- " << spread << " over " << measured << " drawings, riseError " << error
            << " on average; over 1: " << overBound << ", over 1 + riseError: " << overBoundAndError << std::endl;
  EXPECT_GT(error / spread, 0.3);
  EXPECT_LT(error / spread, 1.);
  EXPECT_GT(overBound, 0);
  EXPECT_LE(overBoundAndError, 0.6 * overBound);
}
