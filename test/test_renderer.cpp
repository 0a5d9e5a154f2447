/*
  The renderer is the ground truth of every other test: its images must agree with the projection of
  the landmark centres (vpMeterPixelConversion), be anti-aliased, and show the background where rays
  miss the sheet.
*/
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>

#include <gtest/gtest.h>

#include <visp3/core/vpMath.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl/vpSSLPattern.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include "ssl_test_utils.h"

namespace {
const vpCameraParameters kCam(600., 600., 320., 240.);

double dist(const vpImagePoint &a, const vpImagePoint &b)
{
  return vpImagePoint::distance(a, b);
}

// Rendered darkness centroid of landmark k, over a disc that covers its projected ellipse and its
// anti-aliased edge. The renderer's background must be white: the disc may reach beyond the sheet.
vpImagePoint renderedCentroid(const vpSSLRenderer &renderer, const vpImage<unsigned char> &I,
                              const vpHomogeneousMatrix &cMo, size_t k)
{
  const vpSSLTargetLandmark &l = renderer.getTarget().getLandmark(k);
  const double a = sslt::apparentRadius(renderer.getCameraParameters(), cMo, l.x, l.y, l.radius);
  return sslt::darknessCentroid(I, renderer.projectLandmarks(cMo)[k], a + 1.5);
}
} // namespace

TEST(Renderer, GroundTruthAgreesWithImageFrontoParallel)
{
  vpSSLRenderer renderer(kCam, 640, 480);
  renderer.setReflectances(0., 1., 1.);
  vpImage<unsigned char> I;
  // Fronto-parallel, a circle images to a circle around the projected centre: the darkness centroid is
  // the centre whatever the distance or the in-plane offset.
  for (double Z : {0.6, 1., 2., 4.}) {
    for (double tx : {0., 0.037}) {
      vpHomogeneousMatrix cMo = sslt::lookAt(Z);
      cMo[0][3] = tx * Z;
      cMo[1][3] = -0.6 * tx * Z;
      renderer.render(cMo, I);
      const std::vector<vpImagePoint> centres = renderer.projectLandmarks(cMo);
      for (size_t k = 0; k < centres.size(); ++k) {
        EXPECT_LT(dist(renderedCentroid(renderer, I, cMo, k), centres[k]), 0.1)
            << "Z " << Z << " tx " << tx << " landmark " << k;
      }
    }
  }
}

TEST(Renderer, GroundTruthAgreesWithImageTiltedRolledOffAxis)
{
  // A landmark of 2.4 px apparent radius: the perspective shift of its ring centre, ~ f (R/Z)^2, is
  // below 0.01 px, so its darkness centroid must sit on the projected centre. Only a 32 x 32 window
  // around it is rendered (the camera's principal point moved: an exact crop), at 256 samples per pixel.
  const vpSSLTarget target = sslt::singleLandmarkTarget(0.004);
  vpImage<unsigned char> I;
  struct Pose
  {
    double tilt, axis, roll, tx, ty;
  };
  for (const Pose &p : {Pose{30, 0, 0, 0, 0}, Pose{60, 0, 0, 0, 0}, Pose{30, 90, 0, 0, 0}, Pose{60, 45, 20, 0, 0},
                        Pose{0, 0, 35, 0, 0}, Pose{30, 120, 10, 0.25, -0.15}, Pose{60, 200, 70, -0.3, 0.2}}) {
    vpHomogeneousMatrix cMo = sslt::lookAt(1., p.tilt, p.axis, p.roll);
    cMo[0][3] = p.tx;
    cMo[1][3] = p.ty;
    const vpImagePoint full = sslt::projectPoint(kCam, cMo, 0., 0.);
    const double du = std::round(full.get_u()) - 16., dv = std::round(full.get_v()) - 16.;
    vpSSLRenderer renderer(vpCameraParameters(600., 600., 320. - du, 240. - dv), 32, 32);
    renderer.setTarget(target);
    renderer.setSupersampling(16);
    renderer.render(cMo, I);
    const vpImagePoint c = renderer.projectLandmarks(cMo)[0];
    EXPECT_LT(dist(sslt::darknessCentroid(I, c, 5.), c), 0.1)
        << "tilt " << p.tilt << " axis " << p.axis << " roll " << p.roll << " at " << full;
  }
}

TEST(Renderer, BigTiltedLandmarkMatchesForwardProjection)
{
  // At 60 deg, the rings of a large landmark are shifted by perspective; the renderer's backward ray
  // casting must agree with an independent forward projection of the printed pattern.
  vpSSLRenderer renderer(kCam, 640, 480);
  renderer.setTarget(sslt::singleLandmarkTarget(0.1));
  renderer.setReflectances(0., 1., 1.);
  vpImage<unsigned char> I;
  for (double tilt : {30., 60.}) {
    vpHomogeneousMatrix cMo = sslt::lookAt(0.8, tilt, 30., 15.);
    renderer.render(cMo, I);
    const vpImagePoint expected = sslt::forwardDarknessCentroid(kCam, cMo, renderer.getTarget().getLandmark(0));
    const vpImagePoint rendered = renderedCentroid(renderer, I, cMo, 0);
    EXPECT_LT(dist(rendered, expected), 0.1) << "tilt " << tilt;
    std::cout << "tilt " << tilt << ": perspective shift of the darkness centroid from the projected centre "
              << dist(expected, renderer.projectLandmarks(cMo)[0]) << " px" << std::endl;
  }
}

TEST(Renderer, OneSamplePerPixelPaintsEquation4)
{
  // With one sample per pixel, fronto-parallel at 0.5 m, pixel (u, v) sees the sheet point
  // ((u - u0) / px, (v - v0) / py) / 2: its value is vpSSLPattern's, except within rounding of a ring edge.
  vpSSLRenderer renderer(kCam, 640, 480);
  renderer.setSupersampling(1);
  vpImage<unsigned char> I;
  renderer.render(sslt::lookAt(0.5), I);
  const vpSSLTarget &target = renderer.getTarget();
  int painted = 0;
  for (unsigned int v = 0; v < I.getHeight(); ++v) {
    for (unsigned int u = 0; u < I.getWidth(); ++u) {
      const double X = 0.5 * (u - 320.) / 600., Y = 0.5 * (v - 240.) / 600.;
      for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
        const int s = vpSSLPattern::circular(X - l.x, Y - l.y, l.radius, l.p);
        if (s < 0) {
          continue;
        }
        ++painted;
        if (I[v][u] != 255 * s) {
          // Only a point on a ring edge p^(k/2) R may round either way.
          const double k = 2. * std::log(std::hypot(X - l.x, Y - l.y) / l.radius) / std::log(l.p);
          EXPECT_NEAR(k, std::round(k), 1e-9) << "pixel " << u << ", " << v;
        }
      }
    }
  }
  EXPECT_GT(painted, 50000);
}

TEST(Renderer, EdgePixelsAreAntiAliased)
{
  // Outer radius exactly 50 px, centre on the principal point: the edge crosses pixel u = 370 in its middle.
  vpSSLRenderer renderer(kCam, 640, 480);
  renderer.setTarget(sslt::singleLandmarkTarget(50. / 600.));
  vpImage<unsigned char> I;
  renderer.render(sslt::lookAt(1.), I);
  EXPECT_EQ(I[240][368], 0);
  EXPECT_NEAR(I[240][370], 127.5, 10.);
  EXPECT_EQ(I[240][372], 255);
  EXPECT_NEAR(I[240][270], 127.5, 10.);
  EXPECT_NEAR(I[190][320], 127.5, 10.);
}

TEST(Renderer, BackgroundWhereRaysMissTheSheet)
{
  vpSSLRenderer renderer(kCam, 640, 480);
  renderer.setReflectances(0., 1., 0.4);
  const unsigned char bg = 102; // 0.4 * 255
  vpImage<unsigned char> I;
  renderer.render(sslt::lookAt(2.), I);
  EXPECT_EQ(I[0][0], bg);      // beyond the sheet's corner
  EXPECT_EQ(I[240][320], 255); // the sheet's paper at the origin, between the landmarks
  // Target behind the camera: nothing is hit.
  renderer.render(sslt::lookAt(-2.), I);
  for (unsigned int k = 0; k < I.getSize(); ++k) {
    ASSERT_EQ(I.bitmap[k], bg);
  }
  // Seen from behind, the sheet is blank paper: white or background, never ink.
  renderer.render(sslt::lookAt(1., 180., 90., 0.), I);
  EXPECT_EQ(I[240][320], 255);
  for (unsigned int k = 0; k < I.getSize(); ++k) {
    ASSERT_GE(I.bitmap[k], bg);
  }
  // A background image shows through where rays miss.
  vpImage<unsigned char> B(480, 640, 0);
  B[5][7] = 200;
  renderer.setBackgroundImage(B);
  renderer.render(sslt::lookAt(2.), I);
  EXPECT_EQ(I[5][7], 200);
  EXPECT_EQ(I[5][8], 0);
}

TEST(Renderer, RangeAlongCentralRays)
{
  vpSSLRenderer renderer(kCam, 640, 480);
  vpImage<float> R, D;
  renderer.render(sslt::lookAt(2.), R, D);
  EXPECT_NEAR(D[240][320], 2., 1e-6);
  EXPECT_NEAR(D[280][300], 2. * std::sqrt(1. + (20. * 20. + 40. * 40.) / (600. * 600.)), 1e-5);
  EXPECT_TRUE(std::isinf(D[0][0]));
  EXPECT_FLOAT_EQ(R[240][320], 1.f);
}

TEST(Renderer, Ssl3a3At2mShowsBigLandmarkOf30Px)
{
  vpSSLRenderer renderer(kCam, 640, 480);
  vpImage<unsigned char> I;
  const vpHomogeneousMatrix cMo = sslt::lookAt(2.);
  renderer.render(cMo, I);
  const vpImagePoint b = renderer.projectLandmarks(cMo)[0];
  EXPECT_NEAR(sslt::apparentRadius(kCam, cMo, -0.103923, 0., 0.1), 30., 1e-3);
  // The outermost ring is black: the dark extent along the row through B's centre is 2 x 30 px.
  const int v = static_cast<int>(std::round(b.get_v()));
  int left = -1, right = -1;
  for (int u = 0; u < 640; ++u) {
    if (I[v][u] < 128 && std::fabs(u - b.get_u()) < 40.) {
      right = u;
      if (left < 0) {
        left = u;
      }
    }
  }
  EXPECT_NEAR(0.5 * (right - left + 1), 30., 1.);
  vpImageIo::write(I, VISP_SSL_BINARY_DIR "/test_renderer_ssl3a3_2m.png");
}

TEST(Renderer, DistortedCameraCentresAgree)
{
  // ViSP's kdu model cannot invert kud exactly: at kud = -0.05 the best kdu leaves 0.23 px in the image
  // corners and 0.03 px within 200 px of the centre, where the landmarks are.
  double mismatch = 0.;
  const vpCameraParameters cam = sslt::cameraWithDistortion(600., 600., 320., 240., -0.05, 640, 480, &mismatch);
  ASSERT_LT(mismatch, 0.3) << "kdu does not invert kud: the test itself would be biased";
  vpSSLRenderer renderer(cam, 640, 480);
  renderer.setReflectances(0., 1., 1.);
  vpImage<unsigned char> I;
  int nearCentre = 0;
  // Fronto-parallel (no perspective shift of the ring centres), the target pushed towards the distorted
  // periphery: the image agrees with a forward projection everywhere, and the darkness centroid stays
  // on the kud projection of the centre within 150 px of the principal point. (Farther out, the
  // curvature of the distortion across B, 100 px wide, moves its ring centre by up to 0.3 px: real.)
  for (double tx : {0., 0.2, -0.2}) {
    vpHomogeneousMatrix cMo = sslt::lookAt(1.2, 0., 0., 10.);
    cMo[0][3] = tx;
    cMo[1][3] = 0.5 * tx;
    renderer.render(cMo, I);
    const std::vector<vpImagePoint> centres = renderer.projectLandmarks(cMo);
    for (size_t k = 0; k < centres.size(); ++k) {
      const vpImagePoint rendered = renderedCentroid(renderer, I, cMo, k);
      const vpImagePoint expected = sslt::forwardDarknessCentroid(cam, cMo, renderer.getTarget().getLandmark(k));
      EXPECT_LT(dist(rendered, expected), 0.1) << "tx " << tx << " landmark " << k;
      if (dist(centres[k], vpImagePoint(240., 320.)) < 150.) {
        ++nearCentre;
        EXPECT_LT(dist(rendered, centres[k]), 0.2) << "tx " << tx << " landmark " << k;
      }
    }
  }
  EXPECT_GE(nearCentre, 4);
  // Tilted, where ring centres shift by perspective: the image agrees with a forward projection.
  const vpHomogeneousMatrix cMo = sslt::lookAt(1.2, 40., 60., 10.);
  renderer.render(cMo, I);
  for (size_t k = 0; k < renderer.getTarget().size(); ++k) {
    const vpImagePoint expected = sslt::forwardDarknessCentroid(cam, cMo, renderer.getTarget().getLandmark(k));
    EXPECT_LT(dist(renderedCentroid(renderer, I, cMo, k), expected), 0.1) << "landmark " << k;
  }
}

TEST(Renderer, FisheyeImageAgreesWithForwardProjection)
{
  // Kannala-Brandt (a fisheye, on which the paper's detector also ran): rays come from the cached
  // iterative pixel-to-meter inversion. The fisheye's curvature shifts the ring centres of these large
  // landmarks by up to 0.5 px from the projected centres, so compare with the forward projection.
  vpCameraParameters cam;
  cam.initProjWithKannalaBrandtDistortion(300., 300., 160., 120., {-0.02, 0.005, 0., 0.});
  vpSSLRenderer renderer(cam, 320, 240);
  renderer.setReflectances(0., 1., 1.);
  vpImage<unsigned char> I;
  const vpHomogeneousMatrix cMo = sslt::lookAt(0.9);
  renderer.render(cMo, I);
  for (size_t k = 0; k < renderer.getTarget().size(); ++k) {
    const vpImagePoint expected = sslt::forwardDarknessCentroid(cam, cMo, renderer.getTarget().getLandmark(k));
    EXPECT_LT(dist(renderedCentroid(renderer, I, cMo, k), expected), 0.1) << "landmark " << k;
  }
}

TEST(Renderer, SupersamplingAndReflectancesAreChecked)
{
  vpSSLRenderer renderer(kCam, 640, 480);
  EXPECT_THROW(renderer.setSupersampling(0), vpException);
  EXPECT_THROW(renderer.setReflectances(0., 1.2, 0.5), vpException);
  EXPECT_THROW(renderer.setBackgroundImage(vpImage<unsigned char>(10, 10)), vpException);
  EXPECT_THROW(vpSSLRenderer(kCam, 0, 480), vpException);
  vpSSLTarget noSheet;
  EXPECT_THROW(renderer.setTarget(noSheet), vpException);
}

TEST(Renderer, ReportsFrameTime)
{
  // Informative only (no timing assertion): 640x480 at 16 samples per pixel.
  vpSSLRenderer renderer(kCam, 640, 480);
  vpImage<unsigned char> I;
  const vpHomogeneousMatrix cMo = sslt::lookAt(0.5, 20., 30., 10.);
  renderer.render(cMo, I);
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < 5; ++k) {
    renderer.render(cMo, I);
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / 5.;
  std::cout << "640x480 n=4 frame: " << ms << " ms" << std::endl;
  EXPECT_GT(I.getSum(), 0.);
}
