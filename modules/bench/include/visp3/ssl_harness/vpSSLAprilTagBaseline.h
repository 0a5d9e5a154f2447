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
#include <visp3/core/vpRect.h>
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

  /*!
    As detect(I), but reads \e window of \e I first and the whole image only when the window does not give the
    sheet's tag well inside it: what a tracking user does to save the detector most of the image. The window is
    widened by two of AprilTag's 4-pixel threshold tiles and its corner snapped onto their grid, so that every
    pixel near the tag is thresholded as in the whole image; the tag is kept only when its corners lie at least
    getWindowMargin() pixels inside the window's edges (image edges excepted). The tag and its id are then those
    of detect(I), its corners within a fifth of a pixel (AprilTag's quad fit takes near-tied choices that the
    shifted coordinates' rounding can flip; test/test_vs_apriltag.cpp); getNbOthers() counts the other tags of the
    window only.
    \return true when the sheet's tag was found, in the window or in the whole image.
  */
  bool detect(const vpImage<unsigned char> &I, const vpRect &window);

  //! Whether the last detect() read the window alone (false: the whole image was read).
  bool usedWindow() const { return m_usedWindow; }
  //! Distance (px) the tag's corners must keep from a window edge for the window's reading to be kept.
  static double getWindowMargin() { return 16.; }

  //! Whether the last detect() found the sheet's tag.
  bool found() const { return m_found; }
  //! The tag's pose found by the last detect().
  const vpHomogeneousMatrix &getPose() const { return m_cMo; }
  //! Mean of the four corners as vpDetectorAprilTag::getPolygon() gives them.
  const vpImagePoint &getCentre() const { return m_centre; }
  //! The sheet's tag corners found by the last detect(), in vpDetectorAprilTag::getPolygon()'s order.
  const std::vector<vpImagePoint> &getPolygon() const { return m_polygon; }
  //! Tags of other ids seen by the last detect().
  unsigned int getNbOthers() const { return m_nbOthers; }
  //! The ViSP detector (its polygons are in the coordinates of the image or window it last read).
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
  // Reads the tag among the detections of the last vpDetectorAprilTag::detect() on an image whose pixel (0, 0)
  // is \e offset of the caller's image.
  void collect(const vpImagePoint &offset, const vpCameraParameters &cam);

  vpDetectorAprilTag m_detector;
  int m_id;
  double m_tagSize;
  vpCameraParameters m_cam;
  bool m_found;
  bool m_usedWindow = false;
  unsigned int m_nbOthers;
  std::vector<vpImagePoint> m_polygon;
  vpImage<unsigned char> m_window;
  vpHomogeneousMatrix m_cMo;
  vpImagePoint m_centre;
};

#endif
