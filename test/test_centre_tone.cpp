/*
  vpSSLCentreTone::measure(), the test by which the detector turns away round clutter of 10 to 40 px whose outer rings
  pass for a landmark's: on the landmarks of ssl3-a3 rendered by the independent corpus (visp_ssl_bench, no code
  shared with vpSSLRenderer), 10 to 40 px, face-on to 60 degrees off the normal, sharp to blurred by 2.5 px, the centre
  disc's level lies 2 / 3 of the way from the outer black ring's to the white ring's when sharp and face-on (the
  disc's white area), and never below the black ring's (the detector's bound, 0) where the detector reads the
  landmark at all: only where blur has washed the rings out (a minor semi-axis under 4 blur sigmas) does it fall
  below, and there the detector, even without its bull's-eye checks, reads nothing. A drawn dark disc ringed in white
  and grey lies below 0; nothing is measured where the rings leave the image or have one level.
*/

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

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
  double lowest = 1e9, highest = -1e9;
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
          double tone = 0.;
          if (!vpSSLCentreTone::measure(v.getImage(), trueEllipse(t), target.getP(), tone)) {
            // Two rings of one level: blur has left no ring to compare the centre with.
            EXPECT_LT(t.b, 4. * sigma) << what;
            ++washedOut;
            continue;
          }
          ++measured;
          lowest = std::min(lowest, tone);
          highest = std::max(highest, tone);
          if (sigma == 0. && tilt == 0.) {
            EXPECT_NEAR(tone, 2. / 3., 0.1) << what;
          }
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
  std::cout << measured << " landmarks measured: tone from " << lowest << " to " << highest << "; " << washedOut
            << " with rings of one level" << std::endl;
  EXPECT_GE(measured, 150u);
  EXPECT_LE(washedOut, 5u);
}

TEST(CentreTone, DiscDarkerThanItsRingIsBelowZero)
{
  // A dark disc of 0.35 R ringed in white to 0.7 R, then grey to R (levels 30, 200, 90), sharp and blurred by 1 px: the
  // centre lies (30 - 90) / (200 - 90) = -0.55 of the way from the outer ring's level to the white ring's.
  const double R = 20.;
  for (double sigma : {0., 1.}) {
    vpImage<double> D(81, 81, 220.);
    for (int v = 0; v < 81; ++v) {
      for (int u = 0; u < 81; ++u) {
        const double rho = std::hypot(u - 40., v - 40.) / R;
        D[v][u] = rho < 0.35 ? 30. : rho < 0.7 ? 200. : rho < 1. ? 90. : 220.;
      }
    }
    vpImage<double> B = D;
    if (sigma > 0.) {
      vpImageFilter::gaussianBlur(D, B, 7, sigma);
    }
    vpImage<unsigned char> I(81, 81);
    for (unsigned int i = 0; i < I.getSize(); ++i) {
      I.bitmap[i] = static_cast<unsigned char>(B.bitmap[i] + 0.5);
    }
    vpSSLLandmark l;
    l.u = l.v = 40.;
    l.radius = l.minorRadius = R;
    double tone = 1.;
    ASSERT_TRUE(vpSSLCentreTone::measure(I, l, 0.5, tone)) << "sigma " << sigma;
    EXPECT_NEAR(tone, -0.55, sigma == 0. ? 0.05 : 0.2) << "sigma " << sigma;
    // Its rings out of the image, or of one level: nothing measured.
    l.u = 5.;
    EXPECT_FALSE(vpSSLCentreTone::measure(I, l, 0.5, tone));
    vpImage<unsigned char> flat(81, 81, 128);
    l.u = 40.;
    EXPECT_FALSE(vpSSLCentreTone::measure(flat, l, 0.5, tone));
  }
}
