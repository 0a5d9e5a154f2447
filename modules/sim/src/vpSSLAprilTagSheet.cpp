/*!
  \file vpSSLAprilTagSheet.cpp
  \brief AprilTag 36h11 sheet: code bits from OpenCV's aruco dictionary, frames of vpDetectorAprilTag.
*/
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include <opencv2/aruco.hpp>

#include <visp3/core/vpException.h>

namespace {
// 36h11 is 6 x 6 code bits inside a black border one cell wide: 8 cells, and a white quiet border of one
// more cell on each side for the detector to find the black square's edges.
const int kBlackCells = 8;
const double kQuietWidth = 10. / 8.; // width of tag and quiet border, in tag sizes
const int kNbIds = 587;              // ids of DICT_APRILTAG_36h11
const double kA3Width = 0.420, kA3Height = 0.297;

std::string formatMetres(double v)
{
  std::ostringstream os;
  os << v;
  return os.str();
}
} // namespace

vpSSLAprilTagSheet::vpSSLAprilTagSheet() : vpSSLAprilTagSheet(a3(0)) {}

vpSSLAprilTagSheet::vpSSLAprilTagSheet(int id, double tagSize, double sheetWidth, double sheetHeight)
    : m_id(id), m_tagSize(tagSize), m_sheetWidth(sheetWidth), m_sheetHeight(sheetHeight), m_cells()
{
  if (id < 0 || id >= kNbIds) {
    throw vpException(vpException::badValue, "vpSSLAprilTagSheet: tag id %d not in [0, %d] (family 36h11)", id,
                      kNbIds - 1);
  }
  if (!(tagSize > 0. && sheetWidth > 0. && sheetHeight > 0.)) {
    throw vpException(vpException::badValue, "vpSSLAprilTagSheet: tag size %g and sheet %g x %g m must be > 0", tagSize,
                      sheetWidth, sheetHeight);
  }
  // A relative tolerance: largestTagSize() itself must pass.
  if (kQuietWidth * tagSize > std::min(sheetWidth, sheetHeight) * (1. + 1e-12)) {
    throw vpException(vpException::badValue,
                      "vpSSLAprilTagSheet: a %g m tag needs %g m with its quiet border; the sheet is %g x %g m "
                      "(largest tag: %g m)",
                      tagSize, kQuietWidth * tagSize, sheetWidth, sheetHeight, largestTagSize(sheetWidth, sheetHeight));
  }
  cv::Ptr<cv::aruco::Dictionary> dictionary = cv::aruco::getPredefinedDictionary(cv::aruco::DICT_APRILTAG_36h11);
  cv::Mat marker;
  // One pixel per cell, black border included: pixel (r, c) is cell (r, c), white (255) for a 1 bit.
  cv::aruco::drawMarker(dictionary, id, kBlackCells, marker, 1);
  m_cells.resize(kBlackCells * kBlackCells);
  for (int r = 0; r < kBlackCells; ++r) {
    for (int c = 0; c < kBlackCells; ++c) {
      // aruco draws the AprilTag codes turned by 180 degrees from the AprilTag project's images; turning
      // them back puts vpDetectorAprilTag's tag frame where getSheetToTag() says (test_simulator checks it).
      const unsigned char v = marker.at<unsigned char>(kBlackCells - 1 - r, kBlackCells - 1 - c);
      m_cells[r * kBlackCells + c] = v < 128 ? 1 : 0;
    }
  }
}

vpSSLAprilTagSheet vpSSLAprilTagSheet::a3(int id)
{
  return vpSSLAprilTagSheet(id, largestTagSize(kA3Width, kA3Height), kA3Width, kA3Height);
}

double vpSSLAprilTagSheet::largestTagSize(double width, double height)
{
  return std::min(width, height) / kQuietWidth;
}

bool vpSSLAprilTagSheet::isName(const std::string &name)
{
  return name.rfind("apriltag36h11", 0) == 0;
}

vpSSLAprilTagSheet vpSSLAprilTagSheet::fromName(const std::string &name)
{
  if (name == "apriltag36h11-a3") {
    return a3(0);
  }
  int id = -1;
  double tag = 0., w = 0., h = 0.;
  char tail = 0;
  if (std::sscanf(name.c_str(), "apriltag36h11-a3-id%d%c", &id, &tail) == 1) {
    return a3(id);
  }
  if (std::sscanf(name.c_str(), "apriltag36h11-id%d-tag%lf-sheet%lfx%lf%c", &id, &tag, &w, &h, &tail) == 4) {
    return vpSSLAprilTagSheet(id, tag, w, h);
  }
  throw vpException(vpException::badValue,
                    "vpSSLAprilTagSheet: \"%s\" is not an AprilTag sheet name; use apriltag36h11-a3, "
                    "apriltag36h11-a3-id<N> or apriltag36h11-id<N>-tag<SIZE>-sheet<W>x<H>",
                    name.c_str());
}

std::string vpSSLAprilTagSheet::getName() const
{
  const vpSSLAprilTagSheet a3Sheet = a3(m_id);
  if (m_tagSize == a3Sheet.m_tagSize && m_sheetWidth == kA3Width && m_sheetHeight == kA3Height) {
    return m_id == 0 ? "apriltag36h11-a3" : "apriltag36h11-a3-id" + std::to_string(m_id);
  }
  return "apriltag36h11-id" + std::to_string(m_id) + "-tag" + formatMetres(m_tagSize) + "-sheet" +
         formatMetres(m_sheetWidth) + "x" + formatMetres(m_sheetHeight);
}

std::string vpSSLAprilTagSheet::getMessage() const
{
  return "36h11 id: " + std::to_string(m_id);
}

vpHomogeneousMatrix vpSSLAprilTagSheet::getSheetToTag()
{
  return vpHomogeneousMatrix(0., 0., 0., M_PI, 0., 0.);
}

std::vector<vpPoint> vpSSLAprilTagSheet::getCorners() const
{
  const double s = 0.5 * m_tagSize;
  return {vpPoint(-s, -s, 0.), vpPoint(s, -s, 0.), vpPoint(s, s, 0.), vpPoint(-s, s, 0.)};
}

bool vpSSLAprilTagSheet::isBlackCell(unsigned int row, unsigned int col) const
{
  if (row >= static_cast<unsigned int>(kBlackCells) || col >= static_cast<unsigned int>(kBlackCells)) {
    throw vpException(vpException::badValue, "vpSSLAprilTagSheet: cell (%u, %u) not in the 8 x 8 black square", row,
                      col);
  }
  return m_cells[row * kBlackCells + col] != 0;
}
