/*!
  \file vpSSLAprilTagBaseline.h
  \brief The AprilTag baseline of the comparison benchmarks: ViSP's 36h11 detector on one sheet's tag.
*/
#ifndef VP_SSL_APRILTAG_BASELINE_H
#define VP_SSL_APRILTAG_BASELINE_H

#include <limits>
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/detection/vpDetectorAprilTag.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>

/*!
  \class vpSSLAprilTagBaseline
  \ingroup group_ssl_harness
  \brief The AprilTag baseline: vpDetectorAprilTag (36h11) looking for one sheet's tag id, and the tag pose
  from ViSP with the sequence's camera and the sheet's tag size.

  Configuration (checked on ViSP's own benchmark images by test/test_vs_apriltag.cpp): quad decimate 1
  (the full image, so that the farthest tags are read), edge refinement on, pose HOMOGRAPHY_VIRTUAL_VS (the
  homography initialises a virtual visual servoing on the four corners: ViSP's default and its most
  accurate method on those images), one thread (the SSL tracker is timed on one thread too).
*/
class vpSSLAprilTagBaseline
{
public:
  //! Pose error of the baseline on one tag of ViSP's AprilTag benchmark image.
  struct BenchmarkResult
  {
    int id = -1;                                                      //!< Tag id, -1 when not found.
    double positionError = std::numeric_limits<double>::quiet_NaN();  //!< |dt| (m)
    double angleError = std::numeric_limits<double>::quiet_NaN();     //!< Rotation between estimate and truth (deg)
    double rmsTranslation = std::numeric_limits<double>::quiet_NaN(); //!< ViSP testAprilTag's RMS of t (m)
    double rmsThetaU = std::numeric_limits<double>::quiet_NaN();      //!< ViSP testAprilTag's RMS of theta-u (rad)
  };

  //! The detector of \e sheet's tag id, its pose with \e cam and the sheet's tag size.
  vpSSLAprilTagBaseline(const vpSSLAprilTagSheet &sheet, const vpCameraParameters &cam);

  //! Quad decimation (1: full resolution, the default here; 2: ViSP's default, faster, half the range).
  void setQuadDecimate(float d);

  /*!
    Detects the tags in \e I. \return true when the sheet's tag id is among them; its pose is then
    getPose() (the tag frame, vpSSLAprilTagSheet) and its centre getCentre(). Tags of other ids are counted
    by getNbOthers() (false detections when the sheet shows a single tag).
  */
  bool detect(const vpImage<unsigned char> &I);

  //! Whether the last detect() found the sheet's tag.
  bool found() const { return m_found; }
  //! The tag's pose found by the last detect().
  const vpHomogeneousMatrix &getPose() const { return m_cMo; }
  //! Mean of the four corners as vpDetectorAprilTag::getPolygon() gives them.
  const vpImagePoint &getCentre() const { return m_centre; }
  //! Tags of other ids seen by the last detect().
  unsigned int getNbOthers() const { return m_nbOthers; }
  //! The ViSP detector, for its polygons.
  vpDetectorAprilTag &getDetector() { return m_detector; }

  /*!
    Runs the baseline configuration on ViSP's rendered 640x480 36h11 benchmark image
    (\e dir/tag36_11_640x480.png, five tags, truth \e dir/cMo_ID.txt for tag ID) the way ViSP's testAprilTag does:
    camera px = py = 700, u0 = 320, v0 = 240, tags 0-2 of 0.2 m and 3-4 of 0.1 m (black square).
    \return one result per tag id 0..4, found or not (id -1 and NaN errors when not found).
    \exception vpException (ioError) naming the file when an image or truth file cannot be read.
  */
  static std::vector<BenchmarkResult> runOnVispBenchmark(const std::string &dir, float quadDecimate = 1.f);

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

#endif
