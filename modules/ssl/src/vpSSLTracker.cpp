/*!
  \file vpSSLTracker.cpp
  \brief Implementation of vpSSLTracker.
*/
#include <visp3/ssl/vpSSLTracker.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/core/vpThetaUVector.h>

#include <visp3/ssl/vpSSLInputLimits.h>

#include <visp3/ssl/vpSSLFinite.h>
#include <visp3/ssl/vpSSLPointTransform.h>

#include "vpSSLImageCheck.h"

const char *vpSSLTrackerStateName(vpSSLTrackerState state)
{
  switch (state) {
  case SSL_TRACKER_SEARCHING:
    return "searching";
  case SSL_TRACKER_ACQUIRED:
    return "acquired";
  case SSL_TRACKER_TRACKING:
    return "tracking";
  case SSL_TRACKER_LOST:
    return "lost";
  }
  return "?";
}

vpSSLTracker::vpSSLTracker(const vpSSLTarget &target, const vpCameraParameters &cam, const vpHomogeneousMatrix &vMc)
    : m_target(target), m_cam(cam), m_cMv(), m_detector(target), m_estimator(target), m_filter(target, cam),
      m_state(SSL_TRACKER_SEARCHING), m_fullSearchPeriod(10), m_roiSize(100.), m_acquisitionFrames(3),
      m_maxLostFrames(5), m_reinitPixels(5.), m_gateSigmas(3.), m_gateRangeFraction(0.1), m_gateDegrees(30.),
      m_selected(false), m_orientationKnown(false), m_heldLandmark(0), m_disagreeInRow(0), m_pose(), m_autoSmall(true),
      m_smallRadius(30.), m_predictedRadius(std::numeric_limits<double>::infinity()), m_nbReinitialisations(0),
      m_seenInRow(0), m_lostInRow(0), m_nbLandmarks(0), m_hasOdometry(false), m_oMvPrevious(), m_odometryUsed(false),
      m_rois(), m_hadRegions(false), m_regionFrames(0), m_observations(), m_hypotheses(), m_seen(target.size(), false),
      m_seenX(target.size(), 0.), m_seenY(target.size(), 0.)
{
  if (!(cam.get_px() > 0.) || !(cam.get_py() > 0.)) {
    throw vpException(vpException::badValue, "vpSSLTracker: the camera needs positive px and py");
  }
  // Infinite or absurd intrinsics (px = 1e300, u0 = NaN) would give NaN projections, regions and poses.
  vpSSLInputLimits::checkCamera(cam, "vpSSLTracker: camera");
  if (!vpSSLFinite::isFinite(vMc)) {
    throw vpException(vpException::badValue, "vpSSLTracker: vMc (camera to vehicle) is not finite");
  }
  const double t = vpSSLInputLimits::maxMountTranslation();
  if (std::fabs(vMc[0][3]) > t || std::fabs(vMc[1][3]) > t || std::fabs(vMc[2][3]) > t) {
    throw vpException(vpException::badValue, "vpSSLTracker: vMc (camera to vehicle): translation beyond +-%g m", t);
  }
  m_cMv = vMc.inverse();
}

void vpSSLTracker::reset()
{
  m_state = SSL_TRACKER_SEARCHING;
  m_seenInRow = 0;
  m_lostInRow = 0;
  m_nbLandmarks = 0;
  m_hasOdometry = false;
  m_odometryUsed = false;
  m_rois.clear();
  m_hadRegions = false;
  m_hypotheses.clear();
  m_selected = false;
  m_orientationKnown = false;
  m_disagreeInRow = 0;
  m_predictedRadius = std::numeric_limits<double>::infinity();
  std::fill(m_seen.begin(), m_seen.end(), false);
  m_detector.setRegionsOfInterest(m_rois);
}

void vpSSLTracker::setSmallLandmarkRadius(double pixels)
{
  if (!(pixels > 0.) || !std::isfinite(pixels)) {
    throw vpException(vpException::badValue,
                      "vpSSLTracker::setSmallLandmarkRadius: pixels must be a positive number of pixels");
  }
  m_smallRadius = pixels;
}

void vpSSLTracker::setFullSearchPeriod(unsigned int n)
{
  m_fullSearchPeriod = n;
}

void vpSSLTracker::setRoiSize(double side)
{
  if (!(side > 0.) || !std::isfinite(side)) {
    throw vpException(vpException::badValue, "vpSSLTracker::setRoiSize: side must be a positive number of pixels");
  }
  m_roiSize = side;
}

void vpSSLTracker::setSelectionGate(double sigmas, double rangeFraction, double degrees)
{
  if (!(sigmas >= 0.) || !(rangeFraction >= 0.) || !(degrees >= 0.) || !std::isfinite(sigmas) ||
      !std::isfinite(rangeFraction) || !std::isfinite(degrees)) {
    throw vpException(vpException::badValue,
                      "vpSSLTracker::setSelectionGate: sigmas, rangeFraction and degrees must be finite and >= 0");
  }
  m_gateSigmas = sigmas;
  m_gateRangeFraction = rangeFraction;
  m_gateDegrees = degrees;
}

vpHomogeneousMatrix vpSSLTracker::getPose() const
{
  return hasPose() ? m_pose : vpHomogeneousMatrix();
}

bool vpSSLTracker::heldLandmarkEstimate(vpTranslationVector &t) const
{
  const vpSSLTargetLandmark &l = m_target.getLandmark(m_heldLandmark);
  double held[3] = {0., 0., 0.}, sum = 0.;
  for (unsigned int i = 0; i < m_filter.getNbParticles(); ++i) {
    const vpHomogeneousMatrix P = m_filter.getParticlePose(i);
    const double w = m_filter.getParticleWeight(i);
    double c[3];
    vpSSLPointTransform::apply(P, l.x, l.y, l.z, c);
    for (unsigned int r = 0; r < 3; ++r) {
      held[r] += w * c[r];
    }
    sum += w;
  }
  if (!(sum > 0.) || !std::isfinite(held[0] + held[1] + held[2])) {
    return false;
  }
  t = vpTranslationVector(held[0] / sum, held[1] / sum, held[2] / sum);
  return true;
}

bool vpSSLTracker::positionDisagrees() const
{
  const vpSSLPoseHypothesis &best = m_hypotheses.front();
  vpTranslationVector t;
  if (!best.positionOnly || best.landmark != static_cast<int>(m_heldLandmark) || !heldLandmarkEstimate(t)) {
    return false;
  }
  return (best.cMo.getTranslationVector() - t).frobeniusNorm() > m_gateRangeFraction * t.frobeniusNorm();
}

void vpSSLTracker::selectPose()
{
  m_selected = false;
  m_pose = m_filter.getMeanPose();
  if (m_state == SSL_TRACKER_SEARCHING || m_state == SSL_TRACKER_LOST) {
    return;
  }
  const vpTranslationVector tMean = m_pose.getTranslationVector();
  const vpRotationMatrix RMean = m_pose.getRotationMatrix();
  const vpMatrix C = m_filter.getCovariance();
  const double sigmaT = std::sqrt(std::max(0., C[0][0] + C[1][1] + C[2][2]));
  const double sigmaR = std::sqrt(std::max(0., C[3][3] + C[4][4] + C[5][5]));
  const double maxDistance = m_gateSigmas * sigmaT + m_gateRangeFraction * tMean.frobeniusNorm();
  const double maxAngle = m_gateSigmas * sigmaR + vpMath::rad(m_gateDegrees);
  if (!m_orientationKnown) {
    // Only the landmark the filter was initialised on is known. The mean pose does not place it where the
    // particles do (it averages origins spread on a circle around it): the pose is moved so that it does, or so
    // that it sits where this image's position-only hypothesis puts it when that one agrees with the filter.
    const vpSSLTargetLandmark &l = m_target.getLandmark(m_heldLandmark);
    vpTranslationVector t;
    if (!heldLandmarkEstimate(t)) {
      return;
    }
    for (const vpSSLPoseHypothesis &h : m_hypotheses) {
      if (h.positionOnly && h.landmark == static_cast<int>(m_heldLandmark) &&
          (h.cMo.getTranslationVector() - t).frobeniusNorm() <= maxDistance) {
        t = h.cMo.getTranslationVector();
        m_selected = true;
        break;
      }
    }
    const vpTranslationVector offset = RMean * vpTranslationVector(l.x, l.y, l.z);
    m_pose.insert(vpTranslationVector(t[0] - offset[0], t[1] - offset[1], t[2] - offset[2]));
    return;
  }
  // The hypotheses come best first (vpSSLPoseEstimator's ranking of the image): the first that the filter
  // accepts. The ranking is the better judge among hypotheses that all agree with the filter (two branches of
  // a nearly face-on view are close, and the filter's mean is a few degrees off); the filter only vetoes.
  for (const vpSSLPoseHypothesis &h : m_hypotheses) {
    if (h.positionOnly || !vpSSLFinite::isFinite(h.cMo)) {
      continue; // no orientation to choose
    }
    const double distance = (h.cMo.getTranslationVector() - tMean).frobeniusNorm();
    const vpThetaUVector tu(RMean.t() * h.cMo.getRotationMatrix());
    if (distance <= maxDistance && std::sqrt(tu.sumSquare()) <= maxAngle) {
      m_pose = h.cMo;
      m_selected = true;
      return;
    }
  }
}

vpSSLTrackerState vpSSLTracker::track(const vpImage<unsigned char> &I)
{
  if (I.getSize() == 0) {
    throw vpException(vpException::dimensionError, "vpSSLTracker::track: empty image");
  }
  vpSSLImageCheck::input(I, "vpSSLTracker::track");
  m_odometryUsed = false;
  // The odometry reference is dropped: a later track() with odometry cannot know the motion in between.
  m_hasOdometry = false;
  if (m_state != SSL_TRACKER_SEARCHING) {
    m_filter.predict();
  }
  return process(I);
}

vpSSLTrackerState vpSSLTracker::track(const vpImage<unsigned char> &I, const vpHomogeneousMatrix &oMv)
{
  if (I.getSize() == 0) {
    throw vpException(vpException::dimensionError, "vpSSLTracker::track: empty image");
  }
  vpSSLImageCheck::input(I, "vpSSLTracker::track");
  m_odometryUsed = false;
  const bool finite = vpSSLFinite::isFinite(oMv);
  if (m_state != SSL_TRACKER_SEARCHING) {
    if (m_hasOdometry && finite) {
      // Vehicle displacement since the previous image, v1Mv2 = (oMv1)^-1 oMv2 (paper Sec. 3.3).
      m_odometryUsed = m_filter.predict(m_oMvPrevious.inverse() * oMv, m_cMv);
    } else if (!finite) {
      // A non-finite displacement makes the filter spread its particles as for any rejected odometry.
      vpHomogeneousMatrix bad;
      bad[0][3] = std::numeric_limits<double>::quiet_NaN();
      m_filter.predict(bad, m_cMv);
    } else {
      m_filter.predict();
    }
  }
  // A non-finite pose keeps the last finite one as reference, so that one bad reading costs one image.
  if (finite) {
    m_oMvPrevious = oMv;
    m_hasOdometry = true;
  }
  return process(I);
}

void vpSSLTracker::undistort(double u, double v, double &uu, double &vu) const
{
  // The filter projects without distortion: undistorted pixels through the same px, py, u0, v0.
  double x = 0., y = 0.;
  vpPixelMeterConversion::convertPoint(m_cam, u, v, x, y);
  uu = m_cam.get_u0() + m_cam.get_px() * x;
  vu = m_cam.get_v0() + m_cam.get_py() * y;
}

void vpSSLTracker::predictRegions(unsigned int width, unsigned int height)
{
  m_rois.clear();
  m_predictedRadius = std::numeric_limits<double>::infinity();
  if (m_state != SSL_TRACKER_ACQUIRED && m_state != SSL_TRACKER_TRACKING) {
    return; // searching or lost: the whole image
  }
  const vpHomogeneousMatrix cMo = m_filter.getMeanPose();
  const double half = 0.5 * m_roiSize;
  bool allInside = true;
  for (const vpSSLTargetLandmark &l : m_target.getLandmarks()) {
    double c[3];
    vpSSLPointTransform::apply(cMo, l.x, l.y, l.z, c);
    const double X = c[0], Y = c[1], Z = c[2];
    if (!(Z > 0.) || !std::isfinite(X) || !std::isfinite(Y)) {
      allInside = false;
      continue;
    }
    double u = 0., v = 0.;
    vpMeterPixelConversion::convertPoint(m_cam, X / Z, Y / Z, u, v);
    if (u >= 0. && v >= 0. && u < width && v < height) {
      m_predictedRadius = std::min(m_predictedRadius, apparentRadius(cMo, l, u, v));
    }
    const double left = std::max(0., u - half), top = std::max(0., v - half);
    const double right = std::min(static_cast<double>(width), u + half);
    const double bottom = std::min(static_cast<double>(height), v + half);
    if (right <= left || bottom <= top) {
      allInside = false;
      continue;
    }
    m_rois.push_back(vpRect(left, top, right - left, bottom - top));
  }
  // A landmark predicted outside the image may be back in it already: search the whole image. So while the
  // orientation is unknown: the other landmarks are then predicted around the one seen at an arbitrary angle,
  // and regions there would keep the detector from ever seeing them (or from correcting a misreading).
  if (!allInside || !m_orientationKnown) {
    m_rois.clear();
  }
}

double vpSSLTracker::apparentRadius(const vpHomogeneousMatrix &cMo, const vpSSLTargetLandmark &l, double u,
                                    double v) const
{
  // Shortest distance from the projected centre to the projected rim: the rays the detector reads from the
  // centre are this long at least (about the minor semi-axis of the outer ellipse for a small circle).
  const unsigned int nbRays = 16;
  double shortest = std::numeric_limits<double>::infinity();
  for (unsigned int k = 0; k < nbRays; ++k) {
    const double a = 2. * M_PI * k / nbRays;
    const double px = l.x + l.radius * std::cos(a), py = l.y + l.radius * std::sin(a);
    double c[3];
    vpSSLPointTransform::apply(cMo, px, py, l.z, c);
    const double X = c[0], Y = c[1], Z = c[2];
    if (!(Z > 0.)) {
      continue; // the circle crosses the image plane: no sensible radius along this ray
    }
    shortest = std::min(
        shortest, std::hypot(m_cam.get_u0() + m_cam.get_px() * X / Z - u, m_cam.get_v0() + m_cam.get_py() * Y / Z - v));
  }
  return shortest;
}

double vpSSLTracker::innerCopyScale(size_t k, double u, double v, double radius) const
{
  // The pattern repeats at every scale p^k inside the landmark (paper Eq. 1): at close range, where the outer
  // rings leave the image, the detector reads an inner copy of the landmark as the landmark. Only the prediction
  // tells them apart: a radius p^k (k >= 1) times the predicted one, within a third of a ring step, is the copy.
  if (m_state != SSL_TRACKER_ACQUIRED && m_state != SSL_TRACKER_TRACKING && m_state != SSL_TRACKER_LOST) {
    return 1.;
  }
  const vpSSLTargetLandmark &l = m_target.getLandmark(k);
  const double predicted = apparentRadius(m_filter.getMeanPose(), l, u, v);
  if (!(radius > 0.) || !(predicted > 0.) || !std::isfinite(predicted) || !(l.p > 0.) || !(l.p < 1.)) {
    return 1.;
  }
  const double steps = std::log(radius / predicted) / std::log(l.p);
  const double k0 = std::round(steps);
  if (k0 < 1. || k0 > 8. || std::fabs(steps - k0) > 1. / 3.) {
    return 1.;
  }
  return std::pow(l.p, k0);
}

void vpSSLTracker::chooseScale()
{
  if (!m_autoSmall) {
    return;
  }
  if (m_state == SSL_TRACKER_SEARCHING || m_state == SSL_TRACKER_LOST) {
    // Nothing is known of the range: the small-landmark mode finds large landmarks too, the default mode no
    // small one.
    m_detector.setSmallLandmarkMode(true);
  } else if (m_predictedRadius < m_smallRadius) {
    m_detector.setSmallLandmarkMode(true);
  } else if (m_predictedRadius > 1.25 * m_smallRadius) {
    m_detector.setSmallLandmarkMode(false);
  } // in between: keep the mode, so that it does not flip at every image near the boundary
}

vpSSLTrackerState vpSSLTracker::process(const vpImage<unsigned char> &I)
{
  predictRegions(I.getWidth(), I.getHeight());
  chooseScale();
  // Paper Sec. 4.1: while there are regions, every n-th image (the n-th, 2n-th, ... since they appeared) is
  // searched whole all the same, so that a landmark the regions miss is found again.
  if (!m_rois.empty()) {
    if (!m_hadRegions) {
      m_regionFrames = 0;
    }
    ++m_regionFrames;
  }
  m_hadRegions = !m_rois.empty();
  const bool full = m_rois.empty() || (m_fullSearchPeriod > 0 && m_regionFrames % m_fullSearchPeriod == 0);
  m_detector.setRegionsOfInterest(full ? std::vector<vpRect>() : m_rois);
  m_detector.detect(I);

  const vpSSLTargetMatch &match = m_detector.getTargetMatch();
  m_observations.clear();
  m_hypotheses.clear();
  std::fill(m_seen.begin(), m_seen.end(), false);
  if (match.found) {
    std::vector<double> copyScale(m_target.size(), 1.);
    for (size_t k = 0; k < m_target.size(); ++k) {
      const vpSSLLandmark *l = m_detector.getMatchedLandmark(k);
      if (l == nullptr) {
        continue;
      }
      vpSSLObservation o;
      o.label = static_cast<int>(k);
      undistort(l->u, l->v, o.u, o.v);
      copyScale[k] = innerCopyScale(k, o.u, o.v, l->radius);
      o.radius = l->radius / copyScale[k];
      m_observations.push_back(o);
      m_seen[k] = true;
      vpPixelMeterConversion::convertPoint(m_cam, l->u, l->v, m_seenX[k], m_seenY[k]);
    }
    m_hypotheses = m_estimator.estimate(m_detector, m_cam);
    // A position-only hypothesis places its landmark at the range of the radius read (Eq. 6): an inner copy read
    // at p^k of the landmark's size puts it 1 / p^k too far, along the same ray.
    for (vpSSLPoseHypothesis &h : m_hypotheses) {
      if (h.positionOnly && h.landmark >= 0 && static_cast<size_t>(h.landmark) < copyScale.size() &&
          copyScale[static_cast<size_t>(h.landmark)] != 1.) {
        const double scale = copyScale[static_cast<size_t>(h.landmark)];
        h.cMo.insert(h.cMo.getTranslationVector() * scale);
        h.positionSigma *= scale;
        h.depthSigma *= scale;
      }
    }
  }
  m_nbLandmarks = static_cast<unsigned int>(m_observations.size());
  const bool seen = !m_observations.empty() && !m_hypotheses.empty();
  bool initialised = false; // the filter was (re-)initialised from this image's hypotheses

  switch (m_state) {
  case SSL_TRACKER_SEARCHING:
  case SSL_TRACKER_LOST:
    if (seen) {
      m_filter.init(m_hypotheses);
      m_filter.update(m_observations);
      initialised = true;
      m_state = SSL_TRACKER_ACQUIRED;
      m_seenInRow = 1;
      m_lostInRow = 0;
    } else if (m_state == SSL_TRACKER_LOST && ++m_lostInRow > m_maxLostFrames) {
      m_state = SSL_TRACKER_SEARCHING;
    }
    break;
  case SSL_TRACKER_ACQUIRED:
  case SSL_TRACKER_TRACKING:
    if (seen) {
      // One or two landmarks: the identifier's labels are a guess (the paper takes a lone landmark for the big
      // one, so S1 alone becomes B at twice its range). Once the filter knows the orientation its projection
      // is the better guess: the detections go to the nearest projected landmark instead.
      m_unlabelled = m_observations;
      if (m_orientationKnown && m_hypotheses.front().positionOnly) {
        for (vpSSLObservation &o : m_unlabelled) {
          o.label = -1;
        }
      }
      vpSSLParticleFilter::vpUpdateStatus status = m_filter.update(m_unlabelled, m_hypotheses);
      // A cloud far from the target can still pass the filter's hopeless test (a distant pose projects every
      // landmark near the image centre); a full single-frame pose that explains the image much better wins.
      const vpSSLPoseHypothesis &best = m_hypotheses.front();
      if (status != vpSSLParticleFilter::REINITIALISED && !best.positionOnly &&
          best.reprojectionError < 0.5 * m_reinitPixels && reprojectionError(m_filter.getMeanPose()) > m_reinitPixels) {
        m_filter.init(m_hypotheses);
        m_filter.update(m_observations);
        initialised = true;
        ++m_nbReinitialisations;
        // Seen without interruption: a correction, not a new acquisition.
        if (m_state == SSL_TRACKER_TRACKING) {
          status = vpSSLParticleFilter::UPDATED;
        } else {
          status = vpSSLParticleFilter::REINITIALISED;
        }
      }
      // Acquired on one or two landmarks, the filter holds a single reading: when the next images keep placing
      // the landmark elsewhere (a first reading that took S1 for B doubles the range), the first reading was the
      // wrong one. Two images in a row, so that one misreading while the filter is right does not win.
      if (status != vpSSLParticleFilter::REINITIALISED && !initialised && !m_orientationKnown && positionDisagrees()) {
        if (++m_disagreeInRow >= 2) {
          m_filter.init(m_hypotheses);
          m_filter.update(m_observations);
          ++m_nbReinitialisations;
          status = vpSSLParticleFilter::REINITIALISED;
        }
      } else {
        m_disagreeInRow = 0;
      }
      initialised = initialised || status == vpSSLParticleFilter::REINITIALISED;
      if (status == vpSSLParticleFilter::REINITIALISED) {
        // The particles had drifted away from the target: trusted again only after a new acquisition.
        m_state = SSL_TRACKER_ACQUIRED;
        m_seenInRow = 1;
      } else {
        ++m_seenInRow;
        // Not trusted while the image contradicts the single reading the acquisition rested on.
        if ((m_filter.getConverged() || m_seenInRow >= m_acquisitionFrames) && m_disagreeInRow == 0) {
          m_state = SSL_TRACKER_TRACKING;
        }
      }
    } else {
      m_state = SSL_TRACKER_LOST;
      m_seenInRow = 0;
      m_lostInRow = 1;
      if (m_lostInRow > m_maxLostFrames) {
        m_state = SSL_TRACKER_SEARCHING;
      }
    }
    break;
  }
  if (m_state == SSL_TRACKER_SEARCHING) {
    m_seenInRow = 0;
    m_lostInRow = 0;
    m_orientationKnown = false;
  } else if (seen) {
    // A full hypothesis in this image gives the orientation; after an initialisation from one or two landmarks
    // (the filter re-initialised, or a new acquisition) it is unknown again.
    const bool full = !m_hypotheses.front().positionOnly;
    m_orientationKnown = full || (m_orientationKnown && !initialised);
    if (initialised) {
      m_disagreeInRow = 0;
      const vpSSLPoseHypothesis &front = m_hypotheses.front();
      m_heldLandmark = front.positionOnly && front.landmark >= 0 ? static_cast<size_t>(front.landmark) : 0;
    }
  }
  selectPose();
  return m_state;
}

double vpSSLTracker::reprojectionError(const vpHomogeneousMatrix &cMo) const
{
  double sum = 0.;
  for (const vpSSLObservation &o : m_observations) {
    const vpSSLTargetLandmark &l = m_target.getLandmark(static_cast<size_t>(o.label));
    double c[3];
    vpSSLPointTransform::apply(cMo, l.x, l.y, l.z, c);
    const double X = c[0], Y = c[1], Z = c[2];
    if (!(Z > 0.)) {
      return std::numeric_limits<double>::infinity();
    }
    const double du = m_cam.get_u0() + m_cam.get_px() * X / Z - o.u;
    const double dv = m_cam.get_v0() + m_cam.get_py() * Y / Z - o.v;
    sum += du * du + dv * dv;
  }
  return m_observations.empty() ? 0. : std::sqrt(sum / m_observations.size());
}

std::vector<vpFeaturePoint> vpSSLTracker::getFeaturePoints() const
{
  std::vector<vpFeaturePoint> features;
  if (!hasPose()) {
    return features;
  }
  const vpHomogeneousMatrix cMo = getPose();
  for (size_t k = 0; k < m_target.size(); ++k) {
    const vpSSLTargetLandmark &l = m_target.getLandmark(k);
    double c[3];
    vpSSLPointTransform::apply(cMo, l.x, l.y, l.z, c);
    const double X = c[0], Y = c[1], Z = c[2];
    if (!(Z > 0.)) {
      continue; // behind the camera: no feature a servo could use
    }
    vpFeaturePoint s;
    if (m_seen[k] && m_state != SSL_TRACKER_LOST) {
      s.buildFrom(m_seenX[k], m_seenY[k], Z);
    } else {
      s.buildFrom(X / Z, Y / Z, Z);
    }
    features.push_back(s);
  }
  return features;
}
