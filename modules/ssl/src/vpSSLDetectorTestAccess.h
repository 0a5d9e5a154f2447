/*
  Private to vpSSLDetector and its tests: what a tracking frame matched, which the public interface does not give.
  The tests include it through the library's source directory.
*/
#ifndef VP_SSL_DETECTOR_TEST_ACCESS_H
#define VP_SSL_DETECTOR_TEST_ACCESS_H

#include <vector>

#include <visp3/core/vpRect.h>
#include <visp3/ssl/vpSSLDetector.h>

#include "vpSSLDetectorImpl.h"

class vpSSLDetectorTestAccess
{
public:
  // Regions of interest that the last tracking frame matched: those whose landmark was not re-read from their
  // centre (vpSSLDetector::setRegionsOfInterest()). Empty after a full search.
  static const std::vector<vpRect> &getMatchedRegions(const vpSSLDetector &detector)
  {
    return detector.m_impl->getPlanner().getPending();
  }
  // Regions of the last tracking frame matched at the resolution of vpSSLDetector::getMatchingMap():
  // getMatchedRegions() but for those of a full-resolution detector (setDecimation(1)) whose predicted landmark was
  // matched, and read, on the decimated image. Empty after a full search.
  static const std::vector<vpRect> &getMapRegions(const vpSSLDetector &detector)
  {
    return detector.m_impl->getPlanner().getMapRegions();
  }
  // Regions where the last full search at full resolution (default window, no small-landmark mode) computed the
  // matching map: around the candidates of the half image. The map is 0 outside them. Empty after any other
  // search.
  static const std::vector<vpRect> &getCandidateRegions(const vpSSLDetector &detector)
  {
    return detector.m_impl->getCandidateRegions();
  }
};

#endif
