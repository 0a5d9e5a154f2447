#include <visp3/ssl_harness/vpSSLAprilTagFusion.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <visp3/core/vpMath.h>
#include <visp3/core/vpThetaUVector.h>
#include <visp3/core/vpTranslationVector.h>

vpSSLAprilTagFusion::vpSSLAprilTagFusion(double tagSize, const vpCameraParameters &cam, const vpHomogeneousMatrix &vMc)
    : m_target(cornerTarget(tagSize)), m_filter(m_target, cam), m_cam(cam), m_cMv(vMc.inverse())
{
}

vpSSLServoInput vpSSLAprilTagFusion::track(const vpSSLServoInput &detection, const vpHomogeneousMatrix &oMv)
{
  bool finite = true;
  for (unsigned int i = 0; i < 3; ++i) {
    for (unsigned int j = 0; j < 4; ++j) {
      finite = finite && std::isfinite(oMv[i][j]);
    }
  }
  if (m_active) {
    if (m_hasOdometry && finite) {
      m_filter.predict(m_oMvPrevious.inverse() * oMv, m_cMv); // v1Mv2, as vpSSLTracker::track()
    } else {
      m_filter.predict();
    }
  }
  if (finite) {
    m_oMvPrevious = oMv;
    m_hasOdometry = true;
  }
  const bool seen = detection.valid && detection.points.size() == 4;
  if (seen) {
    std::vector<vpSSLObservation> observations;
    for (size_t k = 0; k < 4; ++k) {
      vpSSLObservation o; // radius unknown (0): the filter weighs the corner positions only
      o.label = static_cast<int>(k);
      o.u = m_cam.get_u0() + m_cam.get_px() * detection.points[k].x;
      o.v = m_cam.get_v0() + m_cam.get_py() * detection.points[k].y;
      observations.push_back(o);
    }
    vpSSLPoseHypothesis h;
    h.cMo = detection.cMo;
    h.nbLandmarks = 4;
    const std::vector<vpSSLPoseHypothesis> hypotheses(1, h);
    if (!m_active) {
      m_filter.init(hypotheses);
      m_filter.update(observations);
      m_active = true;
    } else {
      m_filter.update(observations, hypotheses);
    }
    m_lostInRow = 0;
  } else if (m_active && ++m_lostInRow > 5) {
    m_active = false;
  }
  if (!m_active) {
    return vpSSLServoInput::none();
  }
  // As vpSSLTracker's pose: the image's pose when it lies within the filter's uncertainty (its default gate:
  // 3 sigmas plus 10 % of the range, 3 sigmas plus 30 deg), the filter's mean otherwise.
  const vpHomogeneousMatrix mean = m_filter.getMeanPose();
  if (seen) {
    const vpMatrix C = m_filter.getCovariance();
    const double sigmaT = std::sqrt(std::max(0., C[0][0] + C[1][1] + C[2][2]));
    const double sigmaR = std::sqrt(std::max(0., C[3][3] + C[4][4] + C[5][5]));
    const vpTranslationVector tMean = mean.getTranslationVector();
    const double distance = (detection.cMo.getTranslationVector() - tMean).frobeniusNorm();
    const vpThetaUVector tu(mean.getRotationMatrix().t() * detection.cMo.getRotationMatrix());
    if (distance <= 3. * sigmaT + 0.1 * tMean.frobeniusNorm() &&
        std::sqrt(tu.sumSquare()) <= 3. * sigmaR + vpMath::rad(30.)) {
      return detection;
    }
  }
  vpSSLServoInput in = vpSSLServoInput::fromPose(m_target.getPoints(), mean);
  if (seen) {
    for (size_t k = 0; k < 4; ++k) {
      in.points[k].x = detection.points[k].x;
      in.points[k].y = detection.points[k].y;
    }
  }
  in.nbPoints = seen ? 4 : 0;
  return in;
}

vpSSLTarget vpSSLAprilTagFusion::cornerTarget(double tagSize)
{
  vpSSLTarget t;
  const double h = tagSize / 2.;
  const double corners[4][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
  for (int k = 0; k < 4; ++k) {
    vpSSLTargetLandmark l;
    l.name = "C" + std::to_string(k);
    l.x = corners[k][0];
    l.y = corners[k][1];
    l.radius = vpSSLTarget::minRadius();
    t.addLandmark(l);
  }
  return t;
}
