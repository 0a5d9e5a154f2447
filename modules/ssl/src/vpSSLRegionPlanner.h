/*
  Private to vpSSLDetector: which regions of interest a tracking frame re-reads, matches on the decimated image or
  matches at full resolution (paper Sec. 4.1), from the landmarks of the previous frame.
*/
#ifndef VP_SSL_REGION_PLANNER_H
#define VP_SSL_REGION_PLANNER_H

#include <cstddef>
#include <vector>

#include <visp3/core/vpRect.h>
#include <visp3/ssl/vpSSLLandmark.h>

/*
  The regions of interest of the next detections (each centred on a predicted landmark) and the bookkeeping of one
  tracking frame: the regions in which a landmark has been read (filled), those left to match (pending), and how the
  pending ones split between the decimated and the full-resolution matching.
*/
class vpSSLRegionPlanner
{
public:
  // Regions of the next detections (empty: the whole image).
  void setRegions(const std::vector<vpRect> &rois) { m_rois.assign(rois.begin(), rois.end()); }
  const std::vector<vpRect> &getRegions() const { return m_rois; }

  // A new frame: no region filled, none pending, none matched.
  void startFrame();
  // The landmarks of this frame, which the next frame's regions predict.
  void remember(const std::vector<vpSSLLandmark> &landmarks) { m_previous.assign(landmarks.begin(), landmarks.end()); }
  // The landmark of the previous frame nearest to (u, v) and within half its smaller semi-axis, if any.
  const vpSSLLandmark *previousNear(double u, double v) const;

  // Whether a landmark has been read inside region k this frame.
  bool isFilled(size_t k) const { return m_filled[k] != 0; }
  void fill(size_t k) { m_filled[k] = 1; }
  // A landmark read at (u, v) fills the region it was predicted in: among those holding it, the one whose centre is
  // nearest (regions overlap when landmarks are close together in the image).
  void fillNearest(double u, double v);
  // Whether (u, v) lies in a region not filled yet.
  bool isOpen(double u, double v) const;

  // Region k is left to the matching.
  void defer(size_t k);
  const std::vector<vpRect> &getPending() const { return m_pending; }

  // Splits the pending regions: those whose predicted landmark has a smaller semi-axis of \e minRadius or more go to
  // getCoarse(), the others to getFine().
  void splitByResolution(double minRadius);
  // The regions of getCoarse() in which the decimated pass read nothing join getFine().
  void refineUnfilledCoarse();
  const std::vector<vpRect> &getCoarse() const { return m_coarse; }
  const std::vector<vpRect> &getFine() const { return m_fine; }

  // Regions matched into the detector's map this frame.
  void setMapRegions(const std::vector<vpRect> &rois) { m_map.assign(rois.begin(), rois.end()); }
  const std::vector<vpRect> &getMapRegions() const { return m_map; }

private:
  // Whether the landmark region \e r predicts (the previous frame's landmark inside it, nearest its centre) has a
  // smaller semi-axis of \e minRadius or more.
  bool largeLandmarkIn(const vpRect &r, double minRadius) const;

  std::vector<vpRect> m_rois;
  std::vector<vpSSLLandmark> m_previous; // landmarks of the previous frame
  std::vector<char> m_filled;            // whether a landmark has been read inside each region this frame
  std::vector<vpRect> m_pending;         // regions of this frame whose landmark was not re-read directly
  std::vector<size_t> m_pendingIndex;    // their indices in m_rois
  std::vector<vpRect> m_coarse, m_fine;  // pending regions matched on the decimated image, and the others
  std::vector<size_t> m_coarseIndex;     // indices in m_rois of m_coarse
  std::vector<vpRect> m_map;             // regions matched into the map this frame
};

#endif
