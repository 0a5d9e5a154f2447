#include <visp3/ssl_servo/vpSSLServoInput.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <visp3/core/vpMath.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/core/vpRotationMatrix.h>
#include <visp3/ssl/vpSSLFinite.h>
#include <visp3/ssl/vpSSLPointTransform.h>
#include <visp3/ssl/vpSSLTracker.h>

namespace {
} // namespace

vpPoint vpSSLServoPoint::getObjectPoint() const
{
  return vpPoint(oX, oY, oZ);
}

vpFeaturePoint vpSSLServoPoint::getFeature() const
{
  vpFeaturePoint s;
  s.buildFrom(x, y, Z);
  return s;
}

vpSSLServoInput vpSSLServoInput::none()
{
  return vpSSLServoInput();
}

vpSSLServoInput vpSSLServoInput::fromTracker(const vpSSLTracker &tracker)
{
  vpSSLServoInput in;
  if (!tracker.hasPose()) {
    return in;
  }
  const std::vector<vpFeaturePoint> features = tracker.getFeaturePoints();
  const std::vector<vpSSLTargetLandmark> &landmarks = tracker.getTarget().getLandmarks();
  // getFeaturePoints() lists every target landmark in target order while a pose exists; a mismatch would
  // pair a feature with the wrong object point, so it is rejected rather than guessed.
  if (features.empty() || features.size() != landmarks.size()) {
    return in;
  }
  in.points.resize(features.size());
  for (size_t i = 0; i < features.size(); ++i) {
    vpSSLServoPoint &p = in.points[i];
    p.oX = landmarks[i].x;
    p.oY = landmarks[i].y;
    p.oZ = landmarks[i].z;
    p.x = features[i].get_x();
    p.y = features[i].get_y();
    p.Z = features[i].get_Z();
  }
  in.cMo = tracker.getPose();
  in.hasPose = true;
  in.nbPoints = tracker.getNbLandmarks();
  in.valid = true;
  return in;
}

vpSSLServoInput vpSSLServoInput::fromAprilTag(const std::vector<vpImagePoint> &corners, const vpHomogeneousMatrix &cMo,
                                              double tagSize, const vpCameraParameters &cam,
                                              bool zAlignedWithCameraAxis)
{
  vpSSLServoInput in;
  if (corners.size() != 4 || !(tagSize > 0.) || !std::isfinite(tagSize) || !vpSSLFinite::isFinite(cMo)) {
    return in;
  }
  for (const vpImagePoint &ip : corners) {
    if (!std::isfinite(ip.get_u()) || !std::isfinite(ip.get_v())) {
      return in;
    }
  }
  if (!(cam.get_px() > 0.) || !(cam.get_py() > 0.)) {
    return in;
  }
  // vpDetectorAprilTag's tag frame has Y up and Z out of the printed side; the sheet frame (X right, Y down,
  // Z into the sheet) is that frame turned by 180 degrees about X.
  vpHomogeneousMatrix cMs = cMo;
  if (!zAlignedWithCameraAxis) {
    vpHomogeneousMatrix tMs(vpTranslationVector(0., 0., 0.), vpRotationMatrix(vpRxyzVector(M_PI, 0., 0.)));
    cMs = cMo * tMs;
  }
  const double h = tagSize / 2.;
  const double object[4][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};

  // Detected corners in normalised coordinates.
  double xd[4], yd[4];
  for (unsigned int k = 0; k < 4; ++k) {
    vpPixelMeterConversion::convertPoint(cam, corners[k], xd[k], yd[k]);
  }
  // Pair object corners with detected ones: the permutation of least total squared distance to the projections
  // (24 permutations), so that the detector's corner order does not matter.
  double xp[4], yp[4], Zp[4];
  for (unsigned int k = 0; k < 4; ++k) {
    double c[3];
    vpSSLPointTransform::apply(cMs, object[k][0], object[k][1], 0., c);
    Zp[k] = c[2];
    if (!(c[2] > 0.)) {
      return in; // the pose puts the tag behind the camera: not a usable detection
    }
    xp[k] = c[0] / c[2];
    yp[k] = c[1] / c[2];
  }
  int perm[4] = {0, 1, 2, 3};
  int best[4] = {0, 1, 2, 3};
  double bestCost = std::numeric_limits<double>::infinity();
  do {
    double cost = 0.;
    for (unsigned int k = 0; k < 4; ++k) {
      cost += vpMath::sqr(xp[k] - xd[perm[k]]) + vpMath::sqr(yp[k] - yd[perm[k]]);
    }
    if (cost < bestCost) {
      bestCost = cost;
      std::copy(perm, perm + 4, best);
    }
  } while (std::next_permutation(perm, perm + 4));

  in.points.resize(4);
  for (unsigned int k = 0; k < 4; ++k) {
    vpSSLServoPoint &p = in.points[k];
    p.oX = object[k][0];
    p.oY = object[k][1];
    p.oZ = 0.;
    p.x = xd[best[k]];
    p.y = yd[best[k]];
    p.Z = Zp[k];
  }
  in.cMo = cMs;
  in.hasPose = true;
  in.nbPoints = 4;
  in.valid = true;
  return in;
}

vpSSLServoInput vpSSLServoInput::fromPose(const std::vector<vpPoint> &objectPoints, const vpHomogeneousMatrix &cMo)
{
  vpSSLServoInput in;
  in.cMo = cMo;
  in.hasPose = true;
  in.valid = !objectPoints.empty();
  in.points.resize(objectPoints.size());
  for (size_t i = 0; i < objectPoints.size(); ++i) {
    vpSSLServoPoint &p = in.points[i];
    p.oX = objectPoints[i].get_oX();
    p.oY = objectPoints[i].get_oY();
    p.oZ = objectPoints[i].get_oZ();
    double c[3];
    vpSSLPointTransform::apply(cMo, p.oX, p.oY, p.oZ, c);
    p.Z = c[2];
    // A point behind the camera keeps its negative depth: the law reports it instead of servoing on it.
    p.x = c[2] != 0. ? c[0] / c[2] : std::numeric_limits<double>::quiet_NaN();
    p.y = c[2] != 0. ? c[1] / c[2] : std::numeric_limits<double>::quiet_NaN();
    if (c[2] > 0.) {
      ++in.nbPoints;
    }
  }
  return in;
}
