/*!
  \file vpSSLAprilTagSheet.h
  \brief A printed sheet carrying one AprilTag 36h11: the baseline target of the same paper size as ssl3-a3.
*/
#ifndef VP_SSL_APRILTAG_SHEET_H
#define VP_SSL_APRILTAG_SHEET_H

#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpPoint.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLAprilTagSheet
  \ingroup group_ssl_sim
  \brief One AprilTag 36h11 printed in the middle of a white sheet, for the AprilTag baseline rendered by
  vpSSLRenderer on the same views as the SSL targets.

  The tag is 10 x 10 cells: a white quiet border one cell wide (the paper), the black border, and the 6 x 6
  code bits. Its \e tag \e size is the side of the black square (8 cells), the size that
  vpDetectorAprilTag::getPose() expects. a3() prints the largest tag whose quiet border still fits on an A3
  sheet held landscape: 10 cells over the 0.297 m height, a tag size of 0.2376 m.

  The code bits come from OpenCV contrib's aruco dictionary DICT_APRILTAG_36h11 (587 ids), turned by
  180 degrees: cv::aruco::drawMarker() draws the AprilTag codes upside down with respect to the AprilTag
  project's own tag images, which is how a user prints them.

  Frames:
  - The \e sheet frame is the one of the SSL targets: origin at the tag centre, X right and Y down on the
    printed sheet, Z into it.
  - The \e tag frame is the one in which vpDetectorAprilTag::getPose() returns the pose with its default
    settings: origin at the tag centre, X right, Y \e up, Z out of the printed side (towards a camera that
    sees the tag). It is the sheet frame turned by 180 degrees about X: getSheetToTag(). With
    vpDetectorAprilTag::setZAlignedWithCameraAxis(true), getPose() returns the sheet frame instead.
  vpSSLRenderer renders the sheet at the pose of the tag frame, so that a sequence's ground truth is what
  vpDetectorAprilTag reports.

  \code
  vpSSLAprilTagSheet sheet = vpSSLAprilTagSheet::a3(0);
  vpSSLRenderer renderer(cam, 640, 480);
  renderer.setAprilTagSheet(sheet);
  renderer.render(cMo, I);                      // cMo: pose of the tag frame
  vpDetectorAprilTag detector(vpDetectorAprilTag::TAG_36h11);
  vpHomogeneousMatrix cMo_est;
  if (detector.detect(I) && detector.getNbObjects() == 1)
    detector.getPose(0, sheet.getTagSize(), cam, cMo_est); // close to cMo
  \endcode
  See tutorial-ssl-simulate-sequence.cpp (option --apriltag).
*/
class VISP_SSL_EXPORT vpSSLAprilTagSheet
{
public:
  //! Tag id 0 on an A3 sheet: a3(0).
  vpSSLAprilTagSheet();
  /*!
    Tag \e id of the 36h11 family, black square of side \e tagSize (m), centred on a white sheet of
    \e sheetWidth x \e sheetHeight (m).
    \exception vpException if \e id is not in [0, 586], a size is not > 0, or the tag with its quiet border
    (1.25 tagSize) does not fit on the sheet.
  */
  vpSSLAprilTagSheet(int id, double tagSize, double sheetWidth, double sheetHeight);

  //! Tag \e id as large as fits with its quiet border on an A3 sheet (0.420 x 0.297 m).
  static vpSSLAprilTagSheet a3(int id = 0);
  //! Side of the black square of the largest tag whose quiet border fits on a \e width x \e height sheet.
  static double largestTagSize(double width, double height);
  //! True for names made by getName(): those starting with "apriltag36h11".
  static bool isName(const std::string &name);
  /*!
    The sheet a getName() text describes: "apriltag36h11-a3" (id 0), "apriltag36h11-a3-id<N>", or
    "apriltag36h11-id<N>-tag<SIZE>-sheet<W>x<H>" (metres).
    \exception vpException on any other text.
  */
  static vpSSLAprilTagSheet fromName(const std::string &name);

  //! Name for sequence.json's "target": "apriltag36h11-a3" for a3(0), see fromName().
  std::string getName() const;
  //! The message vpDetectorAprilTag gives this tag: "36h11 id: <id>".
  std::string getMessage() const;
  int getId() const { return m_id; }                      ///< Tag id in the 36h11 family.
  double getTagSize() const { return m_tagSize; }         ///< Side of the black square (m).
  double getSheetWidth() const { return m_sheetWidth; }   ///< Sheet width (m).
  double getSheetHeight() const { return m_sheetHeight; } ///< Sheet height (m).
  double getCellSize() const { return m_tagSize / 8.; }   ///< Side of one code cell (m).

  //! Pose of the tag frame in the sheet frame (a rotation of 180 degrees about X); its own inverse.
  static vpHomogeneousMatrix getSheetToTag();
  /*!
    Corners of the black square in the tag frame, in the order of vpDetectorAprilTag::getPolygon() and
    vpDetectorAprilTag::getTagsPoints3D().
  */
  std::vector<vpPoint> getCorners() const;
  /*!
    Whether the cell at \e row (0 at the top of the printed sheet) and \e col (0 on the left) of the 8 x 8
    black square is black.
    \exception vpException if \e row or \e col is not in [0, 7].
  */
  bool isBlackCell(unsigned int row, unsigned int col) const;
  //! The 64 cells, row by row from the top of the printed sheet: 1 black, 0 white.
  const std::vector<unsigned char> &getCells() const { return m_cells; }

private:
  int m_id;
  double m_tagSize;
  double m_sheetWidth;
  double m_sheetHeight;
  std::vector<unsigned char> m_cells;
};

#endif
