/*!
  \file vpSSLTarget.h
  \brief Target model: a set of circular self-similar landmarks on a planar sheet.
*/
#ifndef VP_SSL_TARGET_H
#define VP_SSL_TARGET_H

#include <string>
#include <vector>

#include <visp3/core/vpPoint.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \struct vpSSLTargetLandmark
  \ingroup group_ssl
  \brief One circular landmark of a target, in the target frame (metres).
*/
struct VISP_SSL_EXPORT vpSSLTargetLandmark
{
  std::string name;   ///< Label used in outputs ("B", "S1", "S2" for ssl3-a3).
  double x = 0.;      ///< Centre X in the target frame (m).
  double y = 0.;      ///< Centre Y in the target frame (m).
  double z = 0.;      ///< Centre Z in the target frame (m); 0 for a flat sheet.
  double radius = 0.; ///< Outer radius (m).
  double p = 0.5;     ///< Similarity ratio of the square wave (paper Eq. 1).
};

/*!
  \class vpSSLTarget
  \ingroup group_ssl
  \brief A target: circular self-similar landmarks on a printed sheet, in the ViSP/AprilTag target
  frame (X right, Y down, Z into the sheet).

  The default target \c ssl3-a3 (one big landmark B and two small ones S1, S2 on an equilateral
  triangle, A3 sheet) is built in. Other targets are read from a target file:

  \code
  # visp-ssl target file: '#' starts a comment, lengths in metres
  name  my-target
  sheet 0.420 0.297 -0.051 0.0          # width height centre_x centre_y
  landmark B  -0.103923  0.000 0.0 0.100 0.5   # name x y z radius p
  landmark S1  0.051962 -0.090 0.0 0.050 0.5
  landmark S2  0.051962  0.090 0.0 0.050 0.5
  \endcode

  Target file rules (also in doc/target-file.md):
  - One statement per line, fields separated by blanks; '#' starts a comment; blank lines are ignored.
  - <tt>name NAME</tt>: required, once. Names (target and landmarks) are single words.
  - <tt>landmark NAME X Y Z RADIUS [P]</tt>: at least one, at most maxLandmarks() (64); names unique;
    RADIUS in [minRadius(), maxRadius()] = [0.001, 10] m; X, Y, Z within +-maxCoordinate() = 100 m; P in
    [minP(), maxP()] = [0.2, 0.8] (which keeps the number of rings of a landmark bounded) and the same for
    every landmark (the detector matches one square wave). P defaults to 0.5 (the paper's value) only when
    the field is omitted.
  - <tt>sheet WIDTH HEIGHT CENTER_X CENTER_Y</tt>: optional, at most once; WIDTH, HEIGHT in (0,
    maxSheetSide()] = (0, 100] m, the centre within +-100 m. When omitted the sheet is the bounding box of
    the landmark discs plus a margin of the largest radius on every side.
  - Landmarks may not overlap (centre distance in the sheet plane < sum of radii) and must fit on the
    sheet.
  - Any error throws vpException (vpException::ioError when the file cannot be read,
    vpException::badValue otherwise) whose message reads <tt>FILE:LINE: FIELD: problem</tt>, e.g.
    <tt>t.txt:4: radius: not a number: "abc"</tt>.

  \code
  vpSSLTarget target = vpSSLTarget::fromName("ssl3-a3");   // or a path to a target file
  std::vector<vpPoint> P = target.getPoints();              // landmark centres for vpPose
  \endcode
  See tutorial-ssl-target-generator to print one.
*/
class VISP_SSL_EXPORT vpSSLTarget
{
public:
  //! An empty target; fill it with addLandmark() or use ssl3a3() / load().
  vpSSLTarget();

  //! The built-in default target ssl3-a3 (doc/target-ssl3-a3.md).
  static vpSSLTarget ssl3a3();

  /*!
    A built-in target by name ("ssl3-a3"), or else a target file path.
    \exception vpException when the name is unknown and no such file can be read.
  */
  static vpSSLTarget fromName(const std::string &nameOrPath);

  /*!
    Reads a target file (format above).
    \exception vpException naming the file, the line and the field on any error.
  */
  static vpSSLTarget load(const std::string &filename);

  /*!
    Writes the target in the target file format; load() reads it back to the identical target (every
    number in its shortest round-trip decimal form).
    \exception vpException if the file cannot be written, or if load() would reject the target (no
    name, no landmark, a landmark off the sheet).
  */
  void save(const std::string &filename) const;

  /*!
    Adds a landmark.
    \exception vpException if its centre, radius or p is out of range, its p differs from the other
    landmarks', it overlaps one, its name is taken or the target already has maxLandmarks().
  */
  void addLandmark(const vpSSLTargetLandmark &landmark);

  //! Most landmarks in one target: 64 (the identifier's hypotheses grow with the cube of the count).
  static constexpr size_t maxLandmarks() { return 64; }
  //! Smallest landmark radius (m): 0.001.
  static constexpr double minRadius() { return 1e-3; }
  //! Largest landmark radius (m): 10.
  static constexpr double maxRadius() { return 10.; }
  //! Largest |X|, |Y|, |Z| of a landmark centre, and of the sheet centre (m): 100.
  static constexpr double maxCoordinate() { return 100.; }
  //! Largest sheet width or height (m): 100.
  static constexpr double maxSheetSide() { return 100.; }
  //! Smallest similarity ratio p: 0.2.
  static constexpr double minP() { return 0.2; }
  //! Largest similarity ratio p: 0.8 (vpSSLRenderer draws log(1e-16) / log(p) rings: 166 at 0.8, 1.6e9 at 0.99999999).
  static constexpr double maxP() { return 0.8; }

  //! Sets the printed sheet: size and centre of the rectangle in the target frame (m).
  //! \exception vpException if a side is not in (0, maxSheetSide()] or the centre not within maxCoordinate().
  void setSheet(double width, double height, double centerX, double centerY);

  //! Sets the target's name.
  void setName(const std::string &name) { m_name = name; }

  //! Target name ("ssl3-a3" for the default).
  const std::string &getName() const { return m_name; }
  //! Number of landmarks.
  size_t size() const { return m_landmarks.size(); }
  //! Landmark \e i. \exception vpException if \e i is out of range.
  const vpSSLTargetLandmark &getLandmark(size_t i) const;
  //! All landmarks, in file order.
  const std::vector<vpSSLTargetLandmark> &getLandmarks() const { return m_landmarks; }
  //! Index of the landmark called \e name, or -1.
  int findLandmark(const std::string &name) const;
  //! Landmark centres as vpPoint (object coordinates set), in landmark order.
  std::vector<vpPoint> getPoints() const;
  //! Similarity ratio shared by all landmarks. \exception vpException if they differ.
  double getP() const;
  //! Largest landmark radius (m).
  double getMaxRadius() const;
  //! Smallest landmark radius (m).
  double getMinRadius() const;

  double getSheetWidth() const { return m_sheetWidth; }     ///< Printed sheet width (m).
  double getSheetHeight() const { return m_sheetHeight; }   ///< Printed sheet height (m).
  double getSheetCenterX() const { return m_sheetCenterX; } ///< Sheet centre X in the target frame (m).
  double getSheetCenterY() const { return m_sheetCenterY; } ///< Sheet centre Y in the target frame (m).

private:
  std::string m_name;
  std::vector<vpSSLTargetLandmark> m_landmarks;
  double m_sheetWidth;
  double m_sheetHeight;
  double m_sheetCenterX;
  double m_sheetCenterY;
  bool m_sheetSet; //!< false while the sheet is the automatic one (bounding box plus a margin).

  void updateAutomaticSheet();
};

#endif
