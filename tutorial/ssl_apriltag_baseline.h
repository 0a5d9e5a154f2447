/*!
  \file ssl_apriltag_baseline.h
  \brief Tutorial-local helpers of tutorial-ssl-vs-apriltag: the AprilTag baseline and the benchmark
  arithmetic (range bands, rates, percentiles, pose errors). Header-only so that the tests include it.
*/
#ifndef SSL_APRILTAG_BASELINE_H
#define SSL_APRILTAG_BASELINE_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpException.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpMath.h>
#include <visp3/detection/vpDetectorAprilTag.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl/vpSSLAprilTagSheet.h>
#include <visp3/ssl/vpSSLImageIo.h>

namespace sslbench {
const double kNaN = std::numeric_limits<double>::quiet_NaN();

/*!
  The AprilTag baseline: vpDetectorAprilTag (36h11) looking for one sheet's tag id, and the tag pose
  from ViSP with the sequence's camera and the sheet's tag size.

  Configuration (checked on ViSP's own benchmark images by test/test_vs_apriltag.cpp): quad decimate 1
  (the full image, so that the farthest tags are read), edge refinement on, pose HOMOGRAPHY_VIRTUAL_VS (the
  homography initialises a virtual visual servoing on the four corners: ViSP's default and its most
  accurate method on those images), one thread (the SSL tracker is timed on one thread too).
*/
class AprilTagBaseline
{
public:
  AprilTagBaseline(const vpSSLAprilTagSheet &sheet, const vpCameraParameters &cam)
      : m_detector(vpDetectorAprilTag::TAG_36h11), m_id(sheet.getId()), m_tagSize(sheet.getTagSize()), m_cam(cam),
        m_found(false), m_nbOthers(0)
  {
    m_detector.setAprilTagQuadDecimate(1.f);
    m_detector.setAprilTagNbThreads(1);
    m_detector.setAprilTagRefineEdges(true);
    m_detector.setAprilTagPoseEstimationMethod(vpDetectorAprilTag::HOMOGRAPHY_VIRTUAL_VS);
  }

  //! Quad decimation (1: full resolution, the default here; 2: ViSP's default, faster, half the range).
  void setQuadDecimate(float d) { m_detector.setAprilTagQuadDecimate(d); }

  /*!
    Detects the tags in \e I. \return true when the sheet's tag id is among them; its pose is then
    getPose() (the tag frame, vpSSLAprilTagSheet) and its centre getCentre(). Tags of other ids are counted
    by getNbOthers() (false detections when the sheet shows a single tag).
  */
  bool detect(const vpImage<unsigned char> &I)
  {
    m_found = false;
    m_nbOthers = 0;
    m_detector.detect(I);
    const std::vector<int> ids = m_detector.getTagsId();
    for (size_t i = 0; i < ids.size(); ++i) {
      if (ids[i] != m_id || m_found) {
        ++m_nbOthers;
        continue;
      }
      m_found = true;
      std::vector<vpImagePoint> p = m_detector.getPolygon(i);
      m_centre = vpImagePoint(0., 0.);
      for (const vpImagePoint &q : p)
        m_centre += q * 0.25;
      m_detector.getPose(i, m_tagSize, m_cam, m_cMo);
    }
    return m_found;
  }

  bool found() const { return m_found; }
  const vpHomogeneousMatrix &getPose() const { return m_cMo; }
  //! Mean of the four corners as vpDetectorAprilTag::getPolygon() gives them.
  const vpImagePoint &getCentre() const { return m_centre; }
  unsigned int getNbOthers() const { return m_nbOthers; }
  vpDetectorAprilTag &getDetector() { return m_detector; }

private:
  vpDetectorAprilTag m_detector;
  int m_id;
  double m_tagSize;
  vpCameraParameters m_cam;
  bool m_found;
  unsigned int m_nbOthers;
  vpHomogeneousMatrix m_cMo;
  vpImagePoint m_centre;
};

//! Position error |t_est - t_true| (m).
inline double positionError(const vpHomogeneousMatrix &est, const vpHomogeneousMatrix &truth)
{
  return (est.getTranslationVector() - truth.getTranslationVector()).frobeniusNorm();
}

//! Angle of the rotation between the two orientations (degrees), in [0, 180].
inline double angleError(const vpHomogeneousMatrix &est, const vpHomogeneousMatrix &truth)
{
  vpRotationMatrix R = truth.getRotationMatrix().t() * est.getRotationMatrix();
  double c = (R[0][0] + R[1][1] + R[2][2] - 1.) / 2.;
  c = std::max(-1., std::min(1., c));
  return vpMath::deg(std::acos(c));
}

//! \e x with \e digits decimals for the Markdown tables, "-" when it was not measured (NaN).
inline std::string fmt(double x, int digits)
{
  if (!std::isfinite(x))
    return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, x);
  return buf;
}

//! The range bands of the report (m): [0,1), [1,2), [2,4), [4,8), [8,12].
inline const std::vector<double> &bandEdges()
{
  static const std::vector<double> edges = {0., 1., 2., 4., 8., 12.};
  return edges;
}

//! Band label "0-1", ... "8-12".
inline std::string bandLabel(size_t b)
{
  const std::vector<double> &e = bandEdges();
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g-%g", e[b], e[b + 1]);
  return buf;
}

//! Index of the band holding \e range, or -1 outside [0, 12] or when not finite; 12 m belongs to the last band.
inline int bandIndex(double range)
{
  const std::vector<double> &e = bandEdges();
  if (!std::isfinite(range) || range < e.front() || range > e.back())
    return -1;
  for (size_t b = 0; b + 1 < e.size(); ++b)
    if (range < e[b + 1])
      return static_cast<int>(b);
  return static_cast<int>(e.size()) - 2;
}

/*!
  Percentile \e p in [0, 100] of \e v with linear interpolation between order statistics (NaN values are
  ignored); NaN when no value is left.
*/
inline double percentile(std::vector<double> v, double p)
{
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty())
    return kNaN;
  std::sort(v.begin(), v.end());
  const double pos = p / 100. * static_cast<double>(v.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(pos));
  const size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

//! What one method did on one frame.
struct FrameResult
{
  bool truthKnown = false;     //!< Whether the frame tells if the target is in view (simulated, or ground truth).
  bool hasTarget = false;      //!< Target in view (ground truth present); meaningful when truthKnown.
  double range = kNaN;         //!< Camera to target distance (m), NaN when unknown.
  std::string water;           //!< Water preset, "" when unknown.
  bool detected = false;       //!< The method reported its target.
  bool falseDetection = false; //!< A detection where there is no target (or of another tag id).
  double centreError = kNaN;   //!< px
  double positionError = kNaN; //!< m
  double angleError = kNaN;    //!< deg; NaN when the orientation is not estimated (see orientationKnown)
  //! Whether the pose's orientation is estimated. False for a position-only pose (the SSL tracker after one
  //! landmark alone): its rotation is a placeholder, so its angle error is left out of the statistics.
  bool orientationKnown = true;
  double timeMs = kNaN;
};

//! Counts and statistics of a set of frames.
struct Stats
{
  size_t nbFrames = 0;     //!< Frames processed.
  size_t nbWithTarget = 0; //!< Frames with the target in view (when known).
  size_t nbDetected = 0;   //!< Of those, frames where the method found it.
  size_t nbUnknown = 0;    //!< Frames where presence is unknown (recordings without truth).
  size_t nbUnknownDetected = 0;
  size_t nbNoTarget = 0;     //!< Frames known to show no target.
  size_t nbFalse = 0;        //!< False detections (on any frame).
  size_t nbPositionOnly = 0; //!< Detected frames with the target whose pose is position-only (no angle error).
  std::vector<size_t> bandFrames, bandDetected;
  std::vector<double> range, centre, position, angle, time; // per frame with target, for medians
  std::vector<double> detectedRange;                        // range of every frame with target (detected or not)
  std::vector<char> detectedFlag;

  Stats() : bandFrames(bandEdges().size() - 1, 0), bandDetected(bandEdges().size() - 1, 0) {}

  void add(const FrameResult &f)
  {
    ++nbFrames;
    time.push_back(f.timeMs);
    if (f.falseDetection)
      ++nbFalse;
    if (!f.truthKnown) {
      ++nbUnknown;
      if (f.detected)
        ++nbUnknownDetected;
      return;
    }
    if (!f.hasTarget) {
      ++nbNoTarget;
      return;
    }
    ++nbWithTarget;
    if (f.detected)
      ++nbDetected;
    if (f.detected && !f.orientationKnown)
      ++nbPositionOnly;
    const int b = bandIndex(f.range);
    if (b >= 0) {
      ++bandFrames[b];
      if (f.detected)
        ++bandDetected[b];
    }
    detectedRange.push_back(f.range);
    detectedFlag.push_back(f.detected ? 1 : 0);
    centre.push_back(f.centreError);
    position.push_back(f.positionError);
    angle.push_back(f.orientationKnown ? f.angleError : kNaN); // percentile() skips NaN
    range.push_back(f.range);
  }

  //! Detection rate on frames with the target; on a recording without any truth, detected frames / frames.
  double rate() const
  {
    if (nbWithTarget > 0)
      return static_cast<double>(nbDetected) / static_cast<double>(nbWithTarget);
    if (nbUnknown > 0)
      return static_cast<double>(nbUnknownDetected) / static_cast<double>(nbUnknown);
    return kNaN;
  }
  //! Rate in band \e b, NaN when the band holds no frame.
  double bandRate(size_t b) const
  {
    return bandFrames[b] ? static_cast<double>(bandDetected[b]) / static_cast<double>(bandFrames[b]) : kNaN;
  }

  /*!
    The largest range still detected in >= \e minRate of the frames: the far edge of the farthest bin of
    \e binWidth metres (bins [0, w), [w, 2w), ...) whose frames are detected at >= \e minRate. NaN when no bin
    qualifies or no range is known.
  */
  double range90(double binWidth = 0.5, double minRate = 0.9) const
  {
    // Only the bins that hold frames, in order: one far range (1e13 m) must not allocate a bin per 0.5 m.
    std::map<double, std::pair<size_t, size_t>> bins; // bin index -> (frames, detected)
    for (size_t i = 0; i < detectedRange.size(); ++i) {
      if (!std::isfinite(detectedRange[i]) || detectedRange[i] < 0.)
        continue;
      std::pair<size_t, size_t> &b = bins[std::floor(detectedRange[i] / binWidth)];
      ++b.first;
      b.second += detectedFlag[i];
    }
    double best = kNaN;
    for (const auto &kv : bins)
      if (static_cast<double>(kv.second.second) >= minRate * static_cast<double>(kv.second.first) - 1e-12)
        best = (kv.first + 1.) * binWidth;
    return best;
  }

  //! Rate over bins of \e binWidth, for the plots: bin centres in \e x, rates in \e y (NaN for empty bins).
  void binnedRate(double binWidth, double maxRange, std::vector<double> &x, std::vector<double> &y) const
  {
    const size_t nb = static_cast<size_t>(std::ceil(maxRange / binWidth));
    std::vector<size_t> n(nb, 0), d(nb, 0);
    for (size_t i = 0; i < detectedRange.size(); ++i) {
      if (!std::isfinite(detectedRange[i]) || detectedRange[i] < 0.)
        continue;
      const size_t k = static_cast<size_t>(std::floor(detectedRange[i] / binWidth));
      if (k < nb) {
        ++n[k];
        d[k] += detectedFlag[i];
      }
    }
    x.assign(nb, 0.);
    y.assign(nb, kNaN);
    for (size_t k = 0; k < nb; ++k) {
      x[k] = (static_cast<double>(k) + 0.5) * binWidth;
      if (n[k])
        y[k] = static_cast<double>(d[k]) / static_cast<double>(n[k]);
    }
  }

  //! Median of \e values over bins of \e binWidth (detected frames only: the others are NaN).
  void binnedMedian(const std::vector<double> &values, double binWidth, double maxRange, std::vector<double> &x,
                    std::vector<double> &y) const
  {
    const size_t nb = static_cast<size_t>(std::ceil(maxRange / binWidth));
    std::vector<std::vector<double>> bins(nb);
    for (size_t i = 0; i < range.size(); ++i) {
      if (!std::isfinite(range[i]) || range[i] < 0. || !std::isfinite(values[i]))
        continue;
      const size_t k = static_cast<size_t>(std::floor(range[i] / binWidth));
      if (k < nb)
        bins[k].push_back(values[i]);
    }
    x.assign(nb, 0.);
    y.assign(nb, kNaN);
    for (size_t k = 0; k < nb; ++k) {
      x[k] = (static_cast<double>(k) + 0.5) * binWidth;
      y[k] = percentile(bins[k], 50.);
    }
  }

  void merge(const Stats &o)
  {
    nbFrames += o.nbFrames;
    nbWithTarget += o.nbWithTarget;
    nbDetected += o.nbDetected;
    nbUnknown += o.nbUnknown;
    nbUnknownDetected += o.nbUnknownDetected;
    nbNoTarget += o.nbNoTarget;
    nbFalse += o.nbFalse;
    nbPositionOnly += o.nbPositionOnly;
    for (size_t b = 0; b < bandFrames.size(); ++b) {
      bandFrames[b] += o.bandFrames[b];
      bandDetected[b] += o.bandDetected[b];
    }
    auto cat = [](std::vector<double> &a, const std::vector<double> &b) { a.insert(a.end(), b.begin(), b.end()); };
    cat(range, o.range);
    cat(centre, o.centre);
    cat(position, o.position);
    cat(angle, o.angle);
    cat(time, o.time);
    cat(detectedRange, o.detectedRange);
    detectedFlag.insert(detectedFlag.end(), o.detectedFlag.begin(), o.detectedFlag.end());
  }
};

//! Pose error of the baseline on one tag of ViSP's AprilTag benchmark image.
struct VispBenchmarkResult
{
  int id = -1;
  double positionError = kNaN;  //!< |dt| (m)
  double angleError = kNaN;     //!< rotation angle between estimate and truth (deg)
  double rmsTranslation = kNaN; //!< ViSP testAprilTag's metric: RMS of the translation components (m)
  double rmsThetaU = kNaN;      //!< ViSP testAprilTag's metric: RMS of the theta-u components (rad)
};

/*!
  Runs the baseline configuration on ViSP's rendered 640x480 36h11 benchmark image
  (\e dir/tag36_11_640x480.png, five tags, truth \e dir/cMo_<id>.txt) the way ViSP's testAprilTag does:
  camera px = py = 700, u0 = 320, v0 = 240, tags 0-2 of 0.2 m and 3-4 of 0.1 m (black square).
  \return one result per tag id 0..4, found or not (id -1 and NaN errors when not found).
  \exception vpException (ioError) naming the file when an image or truth file cannot be read.
*/
inline std::vector<VispBenchmarkResult> runOnVispBenchmark(const std::string &dir, float quadDecimate = 1.f)
{
  const std::string imageName = dir + "/tag36_11_640x480.png";
  if (!vpIoTools::checkFilename(imageName))
    throw vpException(vpException::ioError, "%s: cannot read the image", imageName.c_str());
  vpImage<unsigned char> I;
  vpSSLImageIo::read(I, imageName);
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(700., 700., 320., 240.);
  std::vector<VispBenchmarkResult> results;
  for (int id = 0; id < 5; ++id) {
    const std::string truthName = dir + "/cMo_" + std::to_string(id) + ".txt";
    std::ifstream file(truthName);
    if (!file)
      throw vpException(vpException::ioError, "%s: cannot read the ground-truth pose", truthName.c_str());
    vpHomogeneousMatrix truth;
    truth.load(file);
    // ViSP's test: tag size 0.25 m for the whole 10-cell tag, 8/10 of it for the black square; ids 3, 4 half.
    const double tagSize = (id < 3 ? 0.25 : 0.125) * 8. / 10.;
    AprilTagBaseline baseline(vpSSLAprilTagSheet(id, tagSize, 2. * tagSize, 2. * tagSize), cam);
    baseline.setQuadDecimate(quadDecimate);
    VispBenchmarkResult r;
    if (baseline.detect(I)) {
      r.id = id;
      const vpHomogeneousMatrix &cMo = baseline.getPose();
      r.positionError = positionError(cMo, truth);
      r.angleError = angleError(cMo, truth);
      const vpPoseVector p(cMo), q(truth);
      double st = 0., sr = 0.;
      for (unsigned int k = 0; k < 3; ++k) {
        st += (p[k] - q[k]) * (p[k] - q[k]);
        sr += (p[k + 3] - q[k + 3]) * (p[k + 3] - q[k + 3]);
      }
      r.rmsTranslation = std::sqrt(st / 3.);
      r.rmsThetaU = std::sqrt(sr / 3.);
    }
    results.push_back(r);
  }
  return results;
}

} // namespace sslbench

#endif
