/*!
  \file vpSSLPoseEstimator.h
  \brief Target pose from the landmarks detected in one frame (paper Sec. 3.2).
*/
#ifndef VP_SSL_POSE_ESTIMATOR_H
#define VP_SSL_POSE_ESTIMATOR_H

#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/ssl/vpSSLLandmark.h>
#include <visp3/ssl/vpSSLPoseHypothesis.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl/vpSSLTargetIdentifier.h>

class vpSSLDetector;

/*!
  \class vpSSLPoseEstimator
  \ingroup group_ssl
  \brief Pose hypotheses of the target from one image, following the paper's three cases.

  - One landmark (case 1), or two that are treated as the big one (case 2): the range from its apparent
    radius (Eq. 6, \f$ Z = p_x R / r \f$) along the bearing of its centre gives its position; the result
    is one position-only hypothesis (see vpSSLPoseHypothesis::cMo).
  - Three landmarks (case 3): every solution of cv::solveP3P (up to four), each refined by virtual visual
    servoing (vpPose::poseVirtualVS) from it; those that put a landmark behind the camera are dropped.
  - Four or more landmarks (other targets): one pose, vpPose::computePose (Dementhon then VVS).

  Beyond the paper, the three-landmark hypotheses are ranked by how well they predict what the centres
  do not say: each landmark's outer ellipse (the projection of its tilted circle, size and shape) and
  its Eq. 6 depth. The cost is ellipseError + reprojectionError / (mean apparent radius); with
  setImageAgreement(false) the cost is the reprojection error alone, as in the paper.

  Pixel coordinates go through the camera model (distortion included) to normalised coordinates before
  P3P, so cv::solveP3P is given an identity camera matrix.

  \code
  vpSSLDetector detector;
  vpSSLPoseEstimator estimator(detector.getTarget());
  if (detector.detect(I) && detector.getTargetMatch().found) {
    std::vector<vpSSLPoseHypothesis> h = estimator.estimate(detector, cam);
    if (!h.front().positionOnly) std::cout << h.front().cMo << std::endl;
  }
  \endcode
*/
class VISP_SSL_EXPORT vpSSLPoseEstimator
{
public:
  //! Estimator for \e target (default ssl3-a3).
  explicit vpSSLPoseEstimator(const vpSSLTarget &target = vpSSLTarget::ssl3a3());

  /*!
    Pose hypotheses, best first (never empty).
    \param landmarks : detected landmarks.
    \param match : target identification; match.detection[k] indexes \e landmarks for target landmark k.
    \param cam : camera model.
    \exception vpException when the camera has no positive px/py, when no landmark is matched, or when
    the match does not fit the target or the landmarks.
  */
  std::vector<vpSSLPoseHypothesis> estimate(const std::vector<vpSSLLandmark> &landmarks, const vpSSLTargetMatch &match,
                                            const vpCameraParameters &cam) const;

  //! Same on the last detection of \e detector (which must detect the same target).
  std::vector<vpSSLPoseHypothesis> estimate(const vpSSLDetector &detector, const vpCameraParameters &cam) const;

  /*!
    Ranks the P3P hypotheses by their agreement with the ellipses and radii (default true); false ranks
    them by reprojection error only, as the paper does.
  */
  void setImageAgreement(bool enable) { m_imageAgreement = enable; }
  //! Whether the hypotheses are ranked by agreement with the ellipses and radii.
  bool getImageAgreement() const { return m_imageAgreement; }
  //! The target model.
  const vpSSLTarget &getTarget() const { return m_target; }

  /*!
    Outer ellipse of the circle of \e radius centred at (x, y, z) in the target frame, parallel to the
    target plane, seen at pose \e cMo: semi-axes \e a >= \e b and angle \e theta of the major axis from the u
    axis (px, rad), the exact conic of the pinhole projection (distortion ignored).
    \return false when the circle is not entirely in front of the camera.
  */
  static bool projectCircle(const vpCameraParameters &cam, const vpHomogeneousMatrix &cMo, double x, double y, double z,
                            double radius, double &a, double &b, double &theta);

private:
  vpSSLPoseHypothesis positionOnly(const vpSSLLandmark &l, size_t k, const vpCameraParameters &cam) const;
  void score(vpSSLPoseHypothesis &h, const std::vector<const vpSSLLandmark *> &seen, const std::vector<size_t> &ids,
             const vpCameraParameters &cam) const;

  vpSSLTarget m_target;
  bool m_imageAgreement;
};

#endif
