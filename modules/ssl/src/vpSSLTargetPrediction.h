/*
  Private to vpSSLDetector: where a target's landmarks lie in the image, and of what outer ellipse, as one detected
  landmark's ellipse puts them (vpSSLDetectionPipeline::completeTarget()).
*/
#ifndef VP_SSL_TARGET_PREDICTION_H
#define VP_SSL_TARGET_PREDICTION_H

#include <cstddef>

#include <visp3/ssl/vpSSLLandmark.h>
#include <visp3/ssl/vpSSLTarget.h>

#include "vpSSLEllipseMap.h"

/*
  A landmark's outer ellipse is the image of a circle of the target plane: the affine map that takes the unit circle
  onto it (vpSSLEllipseMap) takes the plane around the landmark to the image, up to a rotation about the plane's
  normal that the ellipse cannot tell (the rotation of the target in the rectified image, as vpSSLTargetIdentifier
  measures it). Given that rotation, every other landmark of the target has a predicted centre, and an outer ellipse
  of the anchor's shape scaled by the ratio of the radii: exact under an affine view (and for a plane parallel to the
  image), and under perspective off by terms that, relative to the landmark's size, halve as the range doubles
  (test_target_prediction).
*/
class vpSSLTargetPrediction
{
public:
  explicit vpSSLTargetPrediction(const vpSSLTarget &target) : m_target(target) {}

  // Anchors the prediction on \e anchor, the detection of the target's landmark \e k.
  void setAnchor(const vpSSLLandmark &anchor, size_t k)
  {
    m_anchor = anchor;
    m_k = k;
    m_map = vpSSLEllipseMap(anchor);
  }

  // The rotation of the target in the rectified image (rad) that puts the target's landmark \e l on the centre of
  // \e detection.
  double rotationTo(const vpSSLLandmark &detection, size_t l) const;

  // The distance of \e detection from the anchor, rectified, over the printed distance of the target's landmark \e l
  // (1 where the detection lies at l's place for the rotation rotationTo() gives).
  double distanceRatio(const vpSSLLandmark &detection, size_t l) const;

  // The outer ellipse of the target's landmark \e j (centre, radius, minorRadius, theta; nothing else set) for the
  // rotation \e phi.
  vpSSLLandmark predict(size_t j, double phi) const;

  // Largest distance (px) from the anchor's centre at which predict() can put landmark \e j, over every rotation.
  double reach(size_t j) const;

private:
  vpSSLTarget m_target;
  vpSSLLandmark m_anchor;
  size_t m_k = 0;
  vpSSLEllipseMap m_map;
};

#endif
