/*!
  \file vpSSLDetectionStats.h
  \brief What a detection method did on one frame, and the counts and statistics of a set of frames.
*/
#ifndef VP_SSL_DETECTION_STATS_H
#define VP_SSL_DETECTION_STATS_H

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

/*!
  \struct vpSSLFrameResult
  \ingroup group_ssl_harness
  \brief What one method did on one frame.
*/
struct vpSSLFrameResult
{
  bool truthKnown = false; //!< Whether the frame tells if the target is in view (simulated, or ground truth).
  bool hasTarget = false;  //!< Target in view (ground truth present); meaningful when truthKnown.
  double range = std::numeric_limits<double>::quiet_NaN(); //!< Camera to target distance (m), NaN when unknown.
  std::string water;                                       //!< Water preset, "" when unknown.
  bool detected = false;                                   //!< The method reported its target.
  bool falseDetection = false; //!< A detection where there is no target (or of another tag id).
  double centreError = std::numeric_limits<double>::quiet_NaN();   //!< px
  double positionError = std::numeric_limits<double>::quiet_NaN(); //!< m
  double angleError = std::numeric_limits<double>::quiet_NaN(); //!< deg; NaN when the orientation is not estimated (see
                                                                //!< orientationKnown)
  //! Whether the pose's orientation is estimated. False for a position-only pose (the SSL tracker after one
  //! landmark alone): its rotation is a placeholder, so its angle error is left out of the statistics.
  bool orientationKnown = true;
  double timeMs = std::numeric_limits<double>::quiet_NaN(); //!< Detection time of the frame (ms).
};

/*!
  \class vpSSLDetectionStats
  \ingroup group_ssl_harness
  \brief Counts and statistics of a set of frames (vpSSLFrameResult): detection rates overall and per range band
  (vpSSLBenchMath::bandEdges()), and the per-frame errors for the medians and the plots.
*/
class vpSSLDetectionStats
{
public:
  size_t nbFrames = 0;               //!< Frames processed.
  size_t nbWithTarget = 0;           //!< Frames with the target in view (when known).
  size_t nbDetected = 0;             //!< Of those, frames where the method found it.
  size_t nbUnknown = 0;              //!< Frames where presence is unknown (recordings without truth).
  size_t nbUnknownDetected = 0;      //!< Of those, frames where the method reported its target.
  size_t nbNoTarget = 0;             //!< Frames known to show no target.
  size_t nbFalse = 0;                //!< False detections (on any frame).
  size_t nbPositionOnly = 0;         //!< Detected frames with the target whose pose is position-only (no angle error).
  std::vector<size_t> bandFrames;    //!< Frames with the target per range band.
  std::vector<size_t> bandDetected;  //!< Of those, detected frames per range band.
  std::vector<double> range;         //!< Per frame with target: true range (m).
  std::vector<double> centre;        //!< Per frame with target: centre error (vpSSLFrameResult::centreError).
  std::vector<double> position;      //!< Per frame with target: position error (vpSSLFrameResult::positionError).
  std::vector<double> angle;         //!< Per frame with target: angle error (deg; NaN when the orientation is unknown).
  std::vector<double> time;          //!< Per frame: detection time (ms).
  std::vector<double> detectedRange; //!< Range of every frame with target (detected or not).
  std::vector<char> detectedFlag;    //!< Whether each frame of detectedRange was detected.

  //! No frame yet.
  vpSSLDetectionStats();

  //! Counts frame \e f.
  void add(const vpSSLFrameResult &f);

  //! Detection rate on frames with the target; on a recording without any truth, detected frames / frames.
  double rate() const;

  //! Rate in band \e b, NaN when the band holds no frame.
  double bandRate(size_t b) const;

  /*!
    The largest range still detected in >= \e minRate of the frames: the far edge of the farthest bin of
    \e binWidth metres (bins [0, w), [w, 2w), ...) whose frames are detected at >= \e minRate. NaN when no bin
    qualifies or no range is known.
  */
  double range90(double binWidth = 0.5, double minRate = 0.9) const;

  //! Rate over bins of \e binWidth, for the plots: bin centres in \e x, rates in \e y (NaN for empty bins).
  void binnedRate(double binWidth, double maxRange, std::vector<double> &x, std::vector<double> &y) const;

  //! Median of \e values over bins of \e binWidth (detected frames only: the others are NaN).
  void binnedMedian(const std::vector<double> &values, double binWidth, double maxRange, std::vector<double> &x,
                    std::vector<double> &y) const;

  //! Adds the frames of \e o.
  void merge(const vpSSLDetectionStats &o);
};

#endif
