// vpSSLDetector's pose interface, shaped as vpDetectorAprilTag::detect(I, tagSize, cam, cMo_vec).
#include <visp3/ssl/vpSSLDetector.h>

#include <visp3/ssl/vpSSLPoseEstimator.h>

bool vpSSLDetector::detect(const vpImage<unsigned char> &I, const vpCameraParameters &cam,
                           std::vector<vpHomogeneousMatrix> &cMo_vec, std::vector<vpHomogeneousMatrix> *cMo_vec2,
                           std::vector<double> *projErrors, std::vector<double> *projErrors2,
                           std::vector<vpTranslationVector> *positions)
{
  cMo_vec.clear();
  if (cMo_vec2 != nullptr) {
    cMo_vec2->clear();
  }
  for (std::vector<double> *e : {projErrors, projErrors2}) {
    if (e != nullptr) {
      e->clear();
    }
  }
  if (positions != nullptr) {
    positions->clear();
  }
  detect(I);
  const vpSSLTargetMatch &match = getTargetMatch();
  if (!match.found || match.nbMatched == 0) {
    return false;
  }
  const std::vector<vpSSLPoseHypothesis> hypotheses = vpSSLPoseEstimator(getTarget()).estimate(*this, cam);
  const vpSSLPoseHypothesis &best = hypotheses.front();
  if (best.positionOnly) {
    // Eq. 6 gives the landmark's centre; its identity rotation is an assumption, not a measurement.
    if (positions != nullptr) {
      positions->push_back(best.cMo.getTranslationVector());
    }
    return false;
  }
  cMo_vec.push_back(best.cMo);
  if (projErrors != nullptr) {
    projErrors->push_back(best.reprojectionError);
  }
  if (hypotheses.size() > 1 && !hypotheses[1].positionOnly) {
    if (cMo_vec2 != nullptr) {
      cMo_vec2->push_back(hypotheses[1].cMo);
    }
    if (projErrors2 != nullptr) {
      projErrors2->push_back(hypotheses[1].reprojectionError);
    }
  }
  return true;
}
