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

namespace {
bool isFinite(const vpHomogeneousMatrix &M)
{
  for (unsigned int i = 0; i < 4; ++i)
    for (unsigned int j = 0; j < 4; ++j)
      if (!std::isfinite(M[i][j]))
        return false;
  return true;
}
} // namespace

vpSSLTracker::vpSSLTracker(const vpSSLTarget &target, const vpCameraParameters &cam, const vpHomogeneousMatrix &vMc)
    : m_target(target), m_cam(cam), m_cMv(), m_detector(target), m_estimator(target), m_filter(target, cam),
      m_state(SSL_TRACKER_SEARCHING), m_fullSearchPeriod(10), m_roiSize(100.), m_acquisitionFrames(3),
      m_maxLostFrames(5), m_reinitPixels(5.), m_nbReinitialisations(0), m_seenInRow(0), m_lostInRow(0),
      m_nbLandmarks(0), m_hasOdometry(false), m_oMvPrevious(), m_odometryUsed(false), m_rois(), m_observations(),
      m_hypotheses(), m_seen(target.size(), false), m_seenX(target.size(), 0.), m_seenY(target.size(), 0.)
{
  if (!(cam.get_px() > 0.) || !(cam.get_py() > 0.)) {
    throw vpException(vpException::badValue, "vpSSLTracker: the camera needs positive px and py");
  }
  if (!isFinite(vMc)) {
    throw vpException(vpException::badValue, "vpSSLTracker: vMc (camera to vehicle) is not finite");
  }
  m_cMv = vMc.inverse();
  m_detector.setFullSearchPeriod(m_fullSearchPeriod);
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
  m_hypotheses.clear();
  std::fill(m_seen.begin(), m_seen.end(), false);
  m_detector.setRegionsOfInterest(m_rois);
}

void vpSSLTracker::setFullSearchPeriod(unsigned int n)
{
  m_fullSearchPeriod = n;
  m_detector.setFullSearchPeriod(n);
}

void vpSSLTracker::setRoiSize(double side)
{
  if (!(side > 0.) || !std::isfinite(side)) {
    throw vpException(vpException::badValue, "vpSSLTracker::setRoiSize: side must be a positive number of pixels");
  }
  m_roiSize = side;
}

vpHomogeneousMatrix vpSSLTracker::getPose() const
{
  return hasPose() ? m_filter.getMeanPose() : vpHomogeneousMatrix();
}

vpSSLTrackerState vpSSLTracker::track(const vpImage<unsigned char> &I)
{
  if (I.getSize() == 0) {
    throw vpException(vpException::dimensionError, "vpSSLTracker::track: empty image");
  }
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
  m_odometryUsed = false;
  const bool finite = isFinite(oMv);
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
  if (m_state != SSL_TRACKER_ACQUIRED && m_state != SSL_TRACKER_TRACKING) {
    return; // searching or lost: the whole image
  }
  const vpHomogeneousMatrix cMo = m_filter.getMeanPose();
  const double half = 0.5 * m_roiSize;
  bool allInside = true;
  for (const vpSSLTargetLandmark &l : m_target.getLandmarks()) {
    const double X = cMo[0][0] * l.x + cMo[0][1] * l.y + cMo[0][2] * l.z + cMo[0][3];
    const double Y = cMo[1][0] * l.x + cMo[1][1] * l.y + cMo[1][2] * l.z + cMo[1][3];
    const double Z = cMo[2][0] * l.x + cMo[2][1] * l.y + cMo[2][2] * l.z + cMo[2][3];
    if (!(Z > 0.) || !std::isfinite(X) || !std::isfinite(Y)) {
      allInside = false;
      continue;
    }
    double u = 0., v = 0.;
    vpMeterPixelConversion::convertPoint(m_cam, X / Z, Y / Z, u, v);
    const double left = std::max(0., u - half), top = std::max(0., v - half);
    const double right = std::min(static_cast<double>(width), u + half);
    const double bottom = std::min(static_cast<double>(height), v + half);
    if (right <= left || bottom <= top) {
      allInside = false;
      continue;
    }
    m_rois.push_back(vpRect(left, top, right - left, bottom - top));
  }
  // A landmark predicted outside the image may be back in it already: search the whole image.
  if (!allInside) {
    m_rois.clear();
  }
}

vpSSLTrackerState vpSSLTracker::process(const vpImage<unsigned char> &I)
{
  predictRegions(I.getWidth(), I.getHeight());
  m_detector.setRegionsOfInterest(m_rois);
  m_detector.detect(I);

  const vpSSLTargetMatch &match = m_detector.getTargetMatch();
  m_observations.clear();
  m_hypotheses.clear();
  std::fill(m_seen.begin(), m_seen.end(), false);
  if (match.found) {
    for (size_t k = 0; k < m_target.size(); ++k) {
      const vpSSLLandmark *l = m_detector.getMatchedLandmark(k);
      if (l == nullptr) {
        continue;
      }
      vpSSLObservation o;
      o.label = static_cast<int>(k);
      undistort(l->u, l->v, o.u, o.v);
      o.radius = l->radius;
      m_observations.push_back(o);
      m_seen[k] = true;
      vpPixelMeterConversion::convertPoint(m_cam, l->u, l->v, m_seenX[k], m_seenY[k]);
    }
    m_hypotheses = m_estimator.estimate(m_detector, m_cam);
  }
  m_nbLandmarks = static_cast<unsigned int>(m_observations.size());
  const bool seen = !m_observations.empty() && !m_hypotheses.empty();

  switch (m_state) {
  case SSL_TRACKER_SEARCHING:
  case SSL_TRACKER_LOST:
    if (seen) {
      m_filter.init(m_hypotheses);
      m_filter.update(m_observations);
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
      vpSSLParticleFilter::vpUpdateStatus status = m_filter.update(m_observations, m_hypotheses);
      // A cloud far from the target can still pass the filter's hopeless test (a distant pose projects every
      // landmark near the image centre); a full single-frame pose that explains the image much better wins.
      const vpSSLPoseHypothesis &best = m_hypotheses.front();
      if (status != vpSSLParticleFilter::REINITIALISED && !best.positionOnly &&
          best.reprojectionError < 0.5 * m_reinitPixels && reprojectionError(m_filter.getMeanPose()) > m_reinitPixels) {
        m_filter.init(m_hypotheses);
        m_filter.update(m_observations);
        ++m_nbReinitialisations;
        // Seen without interruption: a correction, not a new acquisition.
        if (m_state == SSL_TRACKER_TRACKING) {
          status = vpSSLParticleFilter::UPDATED;
        } else {
          status = vpSSLParticleFilter::REINITIALISED;
        }
      }
      if (status == vpSSLParticleFilter::REINITIALISED) {
        // The particles had drifted away from the target: trusted again only after a new acquisition.
        m_state = SSL_TRACKER_ACQUIRED;
        m_seenInRow = 1;
      } else {
        ++m_seenInRow;
        if (m_filter.getConverged() || m_seenInRow >= m_acquisitionFrames) {
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
  }
  return m_state;
}

double vpSSLTracker::reprojectionError(const vpHomogeneousMatrix &cMo) const
{
  double sum = 0.;
  for (const vpSSLObservation &o : m_observations) {
    const vpSSLTargetLandmark &l = m_target.getLandmark(static_cast<size_t>(o.label));
    const double X = cMo[0][0] * l.x + cMo[0][1] * l.y + cMo[0][2] * l.z + cMo[0][3];
    const double Y = cMo[1][0] * l.x + cMo[1][1] * l.y + cMo[1][2] * l.z + cMo[1][3];
    const double Z = cMo[2][0] * l.x + cMo[2][1] * l.y + cMo[2][2] * l.z + cMo[2][3];
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
  const vpHomogeneousMatrix cMo = m_filter.getMeanPose();
  for (size_t k = 0; k < m_target.size(); ++k) {
    const vpSSLTargetLandmark &l = m_target.getLandmark(k);
    const double X = cMo[0][0] * l.x + cMo[0][1] * l.y + cMo[0][2] * l.z + cMo[0][3];
    const double Y = cMo[1][0] * l.x + cMo[1][1] * l.y + cMo[1][2] * l.z + cMo[1][3];
    const double Z = cMo[2][0] * l.x + cMo[2][1] * l.y + cMo[2][2] * l.z + cMo[2][3];
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
