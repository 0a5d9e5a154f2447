/*!
  \file vpSSLCorpusSheet.h
  \brief Printable sheets of the evaluation corpus rasterised with area-integrated edges.
*/
#ifndef VP_SSL_CORPUS_SHEET_H
#define VP_SSL_CORPUS_SHEET_H

#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_bench/vpSSLCorpusTexture.h>

/*!
  \class vpSSLCorpusSheet
  \ingroup group_ssl_bench
  \brief A printed sheet as a mip-mapped texture of paper coverage: 1 where the paper is white, 0 where it is
  inked, the fraction of white paper over a pixel at the edges.

  The SSL sheet evaluates the printed square wave s_p(rho) = floor(2 (log_p rho - floor(log_p rho))) of each
  landmark (outermost ring, s_p = 0, inked) analytically: a pixel through which no ring edge passes takes its
  ring's value, the others are averaged over 4x4 sub-samples (16x16 within 4 px of a centre, where the rings are
  thinner than a pixel). The AprilTag sheet draws a 36h11 tag from cv::aruco's dictionary the same way.
  Coordinates are the target frame's (metres, X right, Y down, the sheet in Z = 0).
*/
class vpSSLCorpusSheet
{
public:
  //! What is printed on the sheet.
  enum Content
  {
    SSL_TARGET, ///< The landmarks of a vpSSLTarget.
    APRILTAG    ///< One AprilTag 36h11 tag.
  };

  /*!
    The sheet of \e target (its sheet rectangle), at \e pixelsPerMetre (10000: 4200 px across an A3 sheet).
    \exception vpException if the target has no landmark.
  */
  static vpSSLCorpusSheet sslTarget(const vpSSLTarget &target, double pixelsPerMetre = 10000.);

  /*!
    A sheet of \e width x \e height metres centred at (\e sheetX, \e sheetY) with the AprilTag 36h11 tag \e id
    whose black square has side \e tagSize (AprilTag's and ViSP's tag size), centred at (\e tagX, \e tagY), its
    first code row towards -Y.
    \exception vpException if the tag does not fit on the sheet or the id is not in the family.
  */
  static vpSSLCorpusSheet aprilTag(int id, double tagSize, double tagX, double tagY, double width, double height,
                                   double sheetX, double sheetY, double pixelsPerMetre = 10000.);

  /*!
    Printed paper fraction (1 white, 0 ink) of the SSL landmarks of \e target at plane point (\e x, \e y): the
    exact square wave, without any pixel.
  */
  static double sslPaper(const vpSSLTarget &target, double x, double y);

  Content getContent() const { return m_content; }                   ///< What is printed.
  const vpSSLCorpusTexture &getTexture() const { return m_texture; } ///< Paper coverage, one channel.
  double getLeft() const { return m_left; }                          ///< Sheet's smallest X (m).
  double getTop() const { return m_top; }                            ///< Sheet's smallest Y (m).
  double getWidth() const { return m_width; }                        ///< Sheet width (m).
  double getHeight() const { return m_height; }                      ///< Sheet height (m).
  double getTagSize() const { return m_tagSize; }                    ///< AprilTag black square side (m), 0 for SSL.
  double getTagX() const { return m_tagX; }                          ///< AprilTag centre X (m).
  double getTagY() const { return m_tagY; }                          ///< AprilTag centre Y (m).
  int getTagId() const { return m_tagId; }                           ///< AprilTag id, -1 for SSL.

private:
  vpSSLCorpusTexture m_texture;
  Content m_content = SSL_TARGET;
  double m_left = 0., m_top = 0., m_width = 0., m_height = 0.;
  double m_tagSize = 0., m_tagX = 0., m_tagY = 0.;
  int m_tagId = -1;
};

#endif
