/*!
  \file vpSSLPeakDetector.h
  \brief Local maxima of the matching map (paper Sec. 3.1).
*/
#ifndef VP_SSL_PEAK_DETECTOR_H
#define VP_SSL_PEAK_DETECTOR_H

#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRect.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \struct vpSSLPeak
  \ingroup group_ssl
  \brief A local maximum of the matching map.
*/
struct VISP_SSL_EXPORT vpSSLPeak
{
  double u = 0.; ///< Sub-pixel column (parabola through the 3 neighbours).
  double v = 0.; ///< Sub-pixel row.
  int value = 0; ///< Map value at the integer maximum.
};

/*!
  \class vpSSLPeakDetector
  \ingroup group_ssl
  \brief Finds the landmark candidates: local maxima of M over a threshold, non-maximum suppression
  and sub-pixel refinement.

  \code
  vpSSLPeakDetector peaks;
  peaks.setThreshold(0.25 * match.getMaxValue());
  std::vector<vpSSLPeak> candidates;
  peaks.detect(M, candidates);
  \endcode
*/
class VISP_SSL_EXPORT vpSSLPeakDetector
{
public:
  vpSSLPeakDetector();

  //! Smallest map value a peak may have (same units as the map).
  void setThreshold(int threshold) { m_threshold = threshold; }
  //! Peaks closer than this (px, Chebyshev distance) to a stronger one are suppressed (>= 1).
  void setMinDistance(unsigned int d);
  //! At most this many peaks are kept, strongest first (>= 1).
  void setMaxPeaks(unsigned int n);
  int getThreshold() const { return m_threshold; }              ///< Peak threshold.
  unsigned int getMinDistance() const { return m_minDistance; } ///< Suppression distance (px).
  unsigned int getMaxPeaks() const { return m_maxPeaks; }       ///< Peak budget.

  /*!
    Peaks of \e M, strongest first.
    \param M : the matching map.
    \param peaks : output, cleared first.
    \param rois : when not empty, only maxima inside these rectangles are considered.
  */
  void detect(const vpImage<int> &M, std::vector<vpSSLPeak> &peaks, const std::vector<vpRect> &rois = {});

private:
  void scanRegion(const vpImage<int> &M, int u0, int v0, int u1, int v1);

  int m_threshold;
  unsigned int m_minDistance;
  unsigned int m_maxPeaks;
  std::vector<vpSSLPeak> m_candidates; // reused between frames
  std::vector<int> m_columns;          // columns of one row over the threshold (scanRegion()), reused
};

#endif
