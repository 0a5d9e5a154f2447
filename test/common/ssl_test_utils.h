/*!
  \file ssl_test_utils.h
  \brief Helpers shared by the tests: poses, synthetic targets, image degradations, ground truth.

  Conventions: pixel centres at integer (u, v), u right, v down (ViSP); angles in degrees; the target
  frame is X right, Y down, Z into the sheet, so cMo = identity rotation faces the printed side.
  Every image transform works in place on a vpImage<unsigned char>, rounding and clamping to [0, 255].
*/
#ifndef SSL_TEST_UTILS_H
#define SSL_TEST_UTILS_H

#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/core/vpRect.h>
#include <visp3/ssl/vpSSLTarget.h>

namespace sslt {
/*!
  Pose cMo of a target whose origin is on the optical axis at \e distance (m). Its plane is tilted by
  \e tiltDeg about the in-plane axis (cos a, sin a, 0) of the camera frame, a = \e tiltAxisDeg from the
  image's u axis towards v, after being rotated in its own plane by \e rollDeg (about its Z axis).
  lookAt(d, 0, 0, 0) is fronto-parallel with the target's X along u and Y along v.
*/
vpHomogeneousMatrix lookAt(double distance, double tiltDeg = 0., double tiltAxisDeg = 0., double rollDeg = 0.);

//! One landmark "L" of outer \e radius (m) at the origin, on a white sheet 5 radius x 5 radius centred on it.
vpSSLTarget singleLandmarkTarget(double radius, double p = 0.5);

/*!
  Motion-blur-like 1-D Gaussian of standard deviation \e sigmaPx (pixels) along the direction at
  \e angleDeg from the u axis towards v. Samples every half pixel along the line (bilinear
  interpolation, borders replicated), truncated at 3 sigma. sigmaPx = 0 leaves I unchanged.
*/
void directionalBlur(vpImage<unsigned char> &I, double sigmaPx, double angleDeg);

//! Adds i.i.d. Gaussian noise of standard deviation \e sigma (grey levels), vpGaussRand seeded with \e seed.
void addGaussianNoise(vpImage<unsigned char> &I, double sigma, long seed);

/*!
  Affine grey-level map I' = mean + contrast * (I - 127.5): black (0) goes to mean - 127.5 contrast and
  white (255) to mean + 127.5 contrast. setContrast(I, 1, 127.5) is the identity; contrast < 0 inverts.
*/
void setContrast(vpImage<unsigned char> &I, double contrast, double mean = 127.5);

//! Paints \e value on every pixel whose centre lies in \e rect (clipped to the image).
void occlude(vpImage<unsigned char> &I, const vpRect &rect, unsigned char value);

//! Mirror image left-right: u -> width - 1 - u (turns a target's handedness).
void mirrorHorizontal(vpImage<unsigned char> &I);

//! Pixel of the target-frame point (X, Y, Z) at pose cMo, distortion included (kud); NaN if Z <= 0 in the camera.
vpImagePoint projectPoint(const vpCameraParameters &cam, const vpHomogeneousMatrix &cMo, double X, double Y,
                          double Z = 0.);

/*!
  Major semi-axis, in pixels, of the image of the circle of \e radius centred at (x, y) in the target
  plane Z = 0 at pose cMo. Method: 360 points of the circle are projected (distortion included), and
  the result is half the largest extent of that point set over directions sampled every 0.25 deg
  (for an ellipse, the widest extent is the major axis; no assumption that the projected centre is
  the ellipse's centre, which it is not under perspective). Accurate to ~1e-4 relative.
  \exception vpException if part of the circle is behind the camera.
*/
double apparentRadius(const vpCameraParameters &cam, const vpHomogeneousMatrix &cMo, double x, double y, double radius);

/*!
  Darkness-weighted image centroid of landmark \e l at pose cMo by forward projection (distortion included): the
  printed pattern integrated in polar coordinates on the sheet, each element weighted by its darkness and its image
  area (finite-difference Jacobian of projectPoint()). Under perspective the centroid of a ring's image is not the
  image of its centre: this is what a perfect image shows, independently of any renderer.
*/
vpImagePoint forwardDarknessCentroid(const vpCameraParameters &cam, const vpHomogeneousMatrix &cMo,
                                     const vpSSLTargetLandmark &l);

/*!
  Centroid of the darkness (255 - I) over the pixels within \e radius pixels of \e centre. On a
  fronto-parallel anti-aliased landmark on white paper, with a radius that covers it and stays on the
  sheet, this is the landmark's centre (the pattern is point-symmetric).
*/
vpImagePoint darknessCentroid(const vpImage<unsigned char> &I, const vpImagePoint &centre, double radius);

/*!
  A camera with radial distortion kud (meter -> pixel) and the kdu (pixel -> meter) that best inverts
  it, in least squares over a \e width x \e height image, so that a renderer (which casts rays with kdu)
  and a ground-truth projection (kud) agree. The residual is returned in \e maxMismatchPx if given.
*/
vpCameraParameters cameraWithDistortion(double px, double py, double u0, double v0, double kud, unsigned int width,
                                        unsigned int height, double *maxMismatchPx = nullptr);

//! Median of \e v (mean of the two middle values for an even count); NaN when \e v is empty.
double median(std::vector<double> v);

} // namespace sslt

#endif
