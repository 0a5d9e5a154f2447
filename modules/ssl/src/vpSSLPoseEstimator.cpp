#include <visp3/ssl/vpSSLPoseEstimator.h>

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/core/vpThetaUVector.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLPointTransform.h>
#include <visp3/vision/vpPose.h>

namespace {
// 2x2 shape matrix a^2 d d^T + b^2 n n^T of an ellipse (d along the major axis): unlike (a, b, theta) it is
// continuous when the ellipse becomes a circle and theta loses its meaning.
void shapeMatrix(double a, double b, double theta, double S[3])
{
  const double c = std::cos(theta), s = std::sin(theta);
  S[0] = a * a * c * c + b * b * s * s;
  S[1] = (a * a - b * b) * c * s;
  S[2] = a * a * s * s + b * b * c * c;
}

double ellipseDifference(double a, double b, double theta, const vpSSLLandmark &l)
{
  double P[3], M[3];
  shapeMatrix(a, b, theta, P);
  // A detector that did not fit the minor axis leaves it at 0: compare with a circle then.
  const double minor = l.minorRadius > 0. ? l.minorRadius : l.radius;
  shapeMatrix(l.radius, minor, l.theta, M);
  const double d =
      std::sqrt((P[0] - M[0]) * (P[0] - M[0]) + 2. * (P[1] - M[1]) * (P[1] - M[1]) + (P[2] - M[2]) * (P[2] - M[2]));
  const double n = std::sqrt(M[0] * M[0] + 2. * M[1] * M[1] + M[2] * M[2]);
  return d / n;
}

bool samePose(const vpHomogeneousMatrix &A, const vpHomogeneousMatrix &B)
{
  const vpHomogeneousMatrix D = A.inverse() * B;
  const double angle = vpThetaUVector(D.getRotationMatrix()).getTheta();
  const double dt = (A.getTranslationVector() - B.getTranslationVector()).frobeniusNorm();
  // 0.1 deg and 0.1 % of the range: well below what separates two P3P solutions.
  return angle < vpMath::rad(0.1) && dt < 1e-3 * A.getTranslationVector().frobeniusNorm();
}

// Smallest depth of the target's landmark discs at pose cMo.
double minDepth(const vpSSLTarget &target, const vpHomogeneousMatrix &cMo)
{
  double zmin = 1e300;
  for (const vpSSLTargetLandmark &t : target.getLandmarks()) {
    double c[3];
    vpSSLPointTransform::apply(cMo, t.x, t.y, t.z, c);
    zmin = std::min(zmin, c[2] - t.radius * std::hypot(cMo[2][0], cMo[2][1]));
  }
  return zmin;
}
} // namespace

vpSSLPoseEstimator::vpSSLPoseEstimator(const vpSSLTarget &target) : m_target(target), m_imageAgreement(true)
{
  if (m_target.size() == 0) {
    throw vpException(vpException::badValue, "vpSSLPoseEstimator: the target has no landmark");
  }
}

bool vpSSLPoseEstimator::projectCircle(const vpCameraParameters &cam, const vpHomogeneousMatrix &cMo, double x,
                                       double y, double z, double radius, double &a, double &b, double &theta)
{
  // Plane-to-image homography H = [r1 r2 c] of the circle's plane (normalised coordinates), c its centre.
  double H[3][3], c[3];
  vpSSLPointTransform::apply(cMo, x, y, z, c);
  for (unsigned int i = 0; i < 3; ++i) {
    H[i][0] = cMo[i][0];
    H[i][1] = cMo[i][1];
    H[i][2] = c[i];
  }
  if (!(H[2][2] - radius * std::hypot(H[2][0], H[2][1]) > 0.)) {
    return false;
  }
  // Pixel homography K H; the circle's conic diag(1, 1, -R^2) maps to G^-T Q G^-1 with G = K H.
  vpMatrix G(3, 3);
  const double px = cam.get_px(), py = cam.get_py(), u0 = cam.get_u0(), v0 = cam.get_v0();
  for (unsigned int j = 0; j < 3; ++j) {
    G[0][j] = px * H[0][j] + u0 * H[2][j];
    G[1][j] = py * H[1][j] + v0 * H[2][j];
    G[2][j] = H[2][j];
  }
  vpMatrix Q(3, 3, 0.);
  Q[0][0] = 1.;
  Q[1][1] = 1.;
  Q[2][2] = -radius * radius;
  vpMatrix Gi;
  try {
    Gi = G.inverseByLU();
  } catch (const vpException &) {
    return false;
  }
  const vpMatrix C = Gi.t() * Q * Gi;
  // Centre x0 = -M^-1 g, then (x - x0)^T M (x - x0) = -f0 with f0 = f + g.x0.
  const double m00 = C[0][0], m01 = C[0][1], m11 = C[1][1], g0 = C[0][2], g1 = C[1][2];
  const double det = m00 * m11 - m01 * m01;
  if (!(det > 0.)) {
    return false; // not an ellipse (the circle touches the plane through the optical centre)
  }
  const double xc = -(m11 * g0 - m01 * g1) / det, yc = -(-m01 * g0 + m00 * g1) / det;
  const double f0 = C[2][2] + g0 * xc + g1 * yc;
  const double p = m00 / -f0, r = m01 / -f0, q = m11 / -f0;
  const double mean = 0.5 * (p + q), dev = std::sqrt(0.25 * (p - q) * (p - q) + r * r);
  const double lmin = mean - dev, lmax = mean + dev;
  if (!(lmin > 0.)) {
    return false;
  }
  a = 1. / std::sqrt(lmin);
  b = 1. / std::sqrt(lmax);
  // 0.5 atan2(2r, p - q) is the eigenvector of the largest eigenvalue, the minor axis.
  theta = 0.5 * std::atan2(2. * r, p - q) + M_PI / 2.;
  return true;
}

vpSSLPoseHypothesis vpSSLPoseEstimator::positionOnly(const vpSSLLandmark &l, size_t k,
                                                     const vpCameraParameters &cam) const
{
  const vpSSLTargetLandmark &t = m_target.getLandmark(k);
  if (!(l.radius > 0.)) {
    throw vpException(vpException::badValue,
                      "vpSSLPoseEstimator: landmark %s has apparent radius %g px: no range (Eq. 6)", t.name.c_str(),
                      l.radius);
  }
  // Eq. 6: depth of the landmark centre, along the bearing of its image.
  const double Z = vpSSLDetector::range(l, t.radius, cam);
  double x = 0., y = 0.;
  vpPixelMeterConversion::convertPoint(cam, l.u, l.v, x, y);
  vpSSLPoseHypothesis h;
  h.cMo = vpHomogeneousMatrix(x * Z, y * Z, Z, 0., 0., 0.);
  h.nbLandmarks = 1;
  h.landmark = static_cast<int>(k);
  h.positionOnly = true;
  h.orientationKnown = false;
  // Eq. 6 inherits the relative error of the apparent radius, a few per cent (paper Fig. 5).
  h.depthSigma = 0.05 * Z;
  double a, b, theta;
  if (projectCircle(cam, h.cMo, 0., 0., 0., t.radius, a, b, theta)) {
    h.ellipseError = ellipseDifference(a, b, theta, l);
  }
  h.cost = h.ellipseError;
  return h;
}

void vpSSLPoseEstimator::score(vpSSLPoseHypothesis &h, const std::vector<const vpSSLLandmark *> &seen,
                               const std::vector<size_t> &ids, const vpCameraParameters &cam) const
{
  double e2 = 0., ellipse = 0., depth = 0., meanRadius = 0.;
  unsigned int nbShapes = 0;
  for (size_t i = 0; i < seen.size(); ++i) {
    const vpSSLTargetLandmark &t = m_target.getLandmark(ids[i]);
    const vpSSLLandmark &l = *seen[i];
    vpColVector oP(4, 1.), cP;
    oP[0] = t.x;
    oP[1] = t.y;
    oP[2] = t.z;
    cP = h.cMo * oP;
    double u = 0., v = 0.;
    vpMeterPixelConversion::convertPoint(cam, cP[0] / cP[2], cP[1] / cP[2], u, v);
    e2 += (u - l.u) * (u - l.u) + (v - l.v) * (v - l.v);
    double a, b, theta;
    if (l.radius > 0. && projectCircle(cam, h.cMo, t.x, t.y, t.z, t.radius, a, b, theta)) {
      ellipse += ellipseDifference(a, b, theta, l);
      const double zEq6 = vpSSLDetector::range(l, t.radius, cam);
      depth += std::fabs(cP[2] - zEq6) / zEq6;
      meanRadius += l.radius;
      ++nbShapes;
    }
  }
  h.reprojectionError = std::sqrt(e2 / seen.size());
  h.nbLandmarks = static_cast<unsigned int>(seen.size());
  if (nbShapes > 0) {
    h.ellipseError = ellipse / nbShapes;
    h.depthError = depth / nbShapes;
    meanRadius /= nbShapes;
  }
  // The reprojection error in units of the apparent radius puts it on the scale of the ellipse error; with
  // three points it is ~0 for every P3P solution, so the ellipses decide.
  h.cost = (m_imageAgreement && nbShapes > 0) ? h.ellipseError + h.reprojectionError / meanRadius : h.reprojectionError;
}

std::vector<vpSSLPoseHypothesis> vpSSLPoseEstimator::estimate(const vpSSLDetector &detector,
                                                              const vpCameraParameters &cam) const
{
  return estimate(detector.getLandmarks(), detector.getTargetMatch(), cam);
}

std::vector<vpSSLPoseHypothesis> vpSSLPoseEstimator::estimate(const std::vector<vpSSLLandmark> &landmarks,
                                                              const vpSSLTargetMatch &match,
                                                              const vpCameraParameters &cam) const
{
  if (!(cam.get_px() > 0. && cam.get_py() > 0.)) {
    throw vpException(vpException::badValue,
                      "vpSSLPoseEstimator: camera px = %g, py = %g: set the calibrated focal length (> 0)",
                      cam.get_px(), cam.get_py());
  }
  if (match.detection.size() != m_target.size()) {
    throw vpException(
        vpException::dimensionError, "vpSSLPoseEstimator: the match has %d entries for a target of %d landmarks (%s)",
        static_cast<int>(match.detection.size()), static_cast<int>(m_target.size()), m_target.getName().c_str());
  }
  std::vector<const vpSSLLandmark *> seen;
  std::vector<size_t> ids;
  for (size_t k = 0; k < match.detection.size(); ++k) {
    const int d = match.detection[k];
    if (d < 0) {
      continue;
    }
    if (static_cast<size_t>(d) >= landmarks.size()) {
      throw vpException(vpException::badValue,
                        "vpSSLPoseEstimator: target landmark %s matched to detection %d of only %d",
                        m_target.getLandmark(k).name.c_str(), d, static_cast<int>(landmarks.size()));
    }
    seen.push_back(&landmarks[static_cast<size_t>(d)]);
    ids.push_back(k);
  }
  if (seen.empty()) {
    throw vpException(vpException::badValue, "vpSSLPoseEstimator: no landmark of the target %s was matched",
                      m_target.getName().c_str());
  }

  // Cases 1 and 2: the biggest landmark seen gives the range (Eq. 6); a pair cannot be told apart (Sec. 3.2).
  size_t big = 0;
  for (size_t i = 1; i < seen.size(); ++i) {
    if (m_target.getLandmark(ids[i]).radius > m_target.getLandmark(ids[big]).radius) {
      big = i;
    }
  }
  if (seen.size() < 3) {
    return {positionOnly(*seen[big], ids[big], cam)};
  }

  std::vector<vpPoint> points;
  for (size_t i = 0; i < seen.size(); ++i) {
    const vpSSLTargetLandmark &t = m_target.getLandmark(ids[i]);
    vpPoint P(t.x, t.y, t.z);
    double x = 0., y = 0.;
    vpPixelMeterConversion::convertPoint(cam, seen[i]->u, seen[i]->v, x, y);
    P.set_x(x);
    P.set_y(y);
    points.push_back(P);
  }

  std::vector<vpHomogeneousMatrix> starts;
  if (points.size() == 3) {
    std::vector<cv::Point3d> object;
    std::vector<cv::Point2d> image;
    for (const vpPoint &P : points) {
      object.emplace_back(P.get_oX(), P.get_oY(), P.get_oZ());
      image.emplace_back(P.get_x(), P.get_y());
    }
    const cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
    // OpenCV 4.6's Gao P3P misses real solutions with exactly three points (about 1 view in 5 of this
    // target from 0.6 to 4 m returns none or only a wrong pair); AP3P (Ke and Roumeliotis) misses fewer.
    // The union of both, refined and deduplicated below, holds every solution.
    for (int method : {cv::SOLVEPNP_AP3P, cv::SOLVEPNP_P3P}) {
      std::vector<cv::Mat> rvecs, tvecs;
      try {
        cv::solveP3P(object, image, K, cv::Mat(), rvecs, tvecs, method);
      } catch (const cv::Exception &e) {
        throw vpException(vpException::fatalError, "vpSSLPoseEstimator: cv::solveP3P failed: %s", e.what());
      }
      for (size_t s = 0; s < rvecs.size(); ++s) {
        cv::Mat r, t;
        rvecs[s].convertTo(r, CV_64F);
        tvecs[s].convertTo(t, CV_64F);
        starts.emplace_back(t.at<double>(0), t.at<double>(1), t.at<double>(2), r.at<double>(0), r.at<double>(1),
                            r.at<double>(2));
      }
    }
  } else {
    vpPose pose;
    pose.addPoints(points);
    vpHomogeneousMatrix cMo;
    if (pose.computePose(vpPose::DEMENTHON_VIRTUAL_VS, cMo)) {
      starts.push_back(cMo);
    }
  }

  std::vector<vpSSLPoseHypothesis> hypotheses;
  for (const vpHomogeneousMatrix &start : starts) {
    if (!(minDepth(m_target, start) > 0.)) {
      continue; // a landmark behind the camera (paper Sec. 3.2: half of the solutions)
    }
    vpSSLPoseHypothesis h;
    h.cMo = start;
    try {
      vpPose pose;
      pose.addPoints(points);
      vpHomogeneousMatrix cMo = start;
      pose.poseVirtualVS(cMo);
      if (minDepth(m_target, cMo) > 0.) {
        h.cMo = cMo;
        h.refined = true;
      }
    } catch (const vpException &) {
      // VVS diverged from this start: the P3P pose itself is kept, flagged as not refined.
    }
    bool duplicate = false;
    for (const vpSSLPoseHypothesis &o : hypotheses) {
      duplicate = duplicate || samePose(o.cMo, h.cMo);
    }
    if (!duplicate) {
      score(h, seen, ids, cam);
      hypotheses.push_back(h);
    }
  }
  if (hypotheses.empty()) {
    // No pose in front of the camera (degenerate centres): fall back on case 1 rather than return nothing.
    return {positionOnly(*seen[big], ids[big], cam)};
  }
  std::stable_sort(hypotheses.begin(), hypotheses.end(),
                   [](const vpSSLPoseHypothesis &a, const vpSSLPoseHypothesis &b) { return a.cost < b.cost; });
  return hypotheses;
}
