/*!
  \file ssl_tutorial_canvas.h
  \brief Tutorial-local drawing that goes to an X window when there is one (vpDisplay overlays, clicks) and into the
  image itself otherwise (vpImageDraw, vpFont), written as PNG files. Header-only, like ssl_tutorial_common.h.
*/
#ifndef SSL_TUTORIAL_CANVAS_H
#define SSL_TUTORIAL_CANVAS_H

#include <memory>
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpFont.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpImageDraw.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/core/vpRect.h>
#include <visp3/gui/vpDisplayX.h>
#include <visp3/io/vpImageIo.h>

#include "ssl_tutorial_common.h"

namespace ssltut {

/*!
  An annotated colour image shown in a window, or, without an X display (ssltut::openDisplay() prints the one-line
  notice), drawn into and written as a PNG file by show(). The same calls draw in both cases.
*/
class Canvas
{
public:
  /*!
    Opens the window (titled \e program) when it can, else creates the folder \e outputDir, where show() writes, and
    prints the notice that the drawings go there.
    \exception UsageError when \e outputDir is an existing file: nothing the user gave is overwritten, nor turned
    into a folder (checked first, with or without a window).
    \exception vpException when the folder cannot be created.
  */
  Canvas(const char *program, const std::string &outputDir)
      : m_outputDir(outputDir), m_font(16, vpFont::GENERIC_MONOSPACE)
  {
    if (vpIoTools::checkFilename(outputDir) && !vpIoTools::checkDirectory(outputDir)) {
      throw UsageError("--output: " + outputDir + ": exists and is not a folder");
    }
    m_image.resize(480, 640, vpRGBa(0));
    m_display = openDisplay(m_image, program, program, "writing the drawings into " + outputDir + "/ instead");
    if (!m_display) {
      vpIoTools::makeDirectory(outputDir);
    }
  }

  //! Whether the drawing goes to a window.
  bool hasWindow() const { return m_display != nullptr; }

  //! Starts a new drawing on \e I (grey), the window following its size.
  void display(const vpImage<unsigned char> &I)
  {
    const bool resized = m_image.getWidth() != I.getWidth() || m_image.getHeight() != I.getHeight();
    vpImageConvert::convert(I, m_image);
    if (m_display && resized) {
      m_display.reset(new vpDisplayX(m_image, vpDisplay::SCALE_AUTO));
    }
    if (m_display) {
      vpDisplay::display(m_image);
    }
  }

  void rectangle(const vpRect &r, const vpColor &color, unsigned int thickness = 1) //!< A rectangle.
  {
    if (m_display) {
      vpDisplay::displayRectangle(m_image, r, color, false, thickness);
    } else {
      vpImageDraw::drawRectangle(m_image, r, color, false, thickness);
    }
  }

  void polygon(const std::vector<vpImagePoint> &p, const vpColor &color, unsigned int thickness = 1) //!< A polygon.
  {
    if (m_display) {
      vpDisplay::displayPolygon(m_image, p, color, thickness);
    } else {
      vpImageDraw::drawPolygon(m_image, p, color, thickness);
    }
  }

  void cross(const vpImagePoint &ip, unsigned int size, const vpColor &color, unsigned int thickness = 1) //!< A cross.
  {
    if (m_display) {
      vpDisplay::displayCross(m_image, ip, size, color, thickness);
    } else {
      vpImageDraw::drawCross(m_image, ip, size, color, thickness);
    }
  }

  //! Text whose top-left corner is \e ip.
  void text(const vpImagePoint &ip, const std::string &s, const vpColor &color)
  {
    if (m_display) {
      vpDisplay::displayText(m_image, ip, s, color);
    } else {
      m_font.drawText(m_image, s, ip, color);
    }
  }

  //! The frame of pose \e cMo, axes of \e size (m): X red, Y green, Z blue with vpColor::none.
  void frame(const vpHomogeneousMatrix &cMo, const vpCameraParameters &cam, double size, const vpColor &color,
             unsigned int thickness = 1)
  {
    if (m_display) {
      vpDisplay::displayFrame(m_image, cMo, cam, size, color, thickness);
    } else {
      vpImageDraw::drawFrame(m_image, cMo, cam, size, color, thickness);
    }
  }

  /*!
    Shows the drawing: in the window (and, with \e waitClick, waits for a click), else writes it to the file
    \e name of the output folder.
    \return with a window, whether a click was made (always true after waiting); without, true.
    \exception vpException when the file cannot be written.
  */
  bool show(const std::string &name, bool waitClick)
  {
    if (m_display) {
      vpDisplay::flush(m_image);
      return vpDisplay::getClick(m_image, waitClick);
    }
    vpImageIo::write(m_image, m_outputDir + "/" + name);
    return true;
  }

private:
  std::string m_outputDir;
  vpImage<vpRGBa> m_image;
  std::unique_ptr<vpDisplay> m_display;
  vpFont m_font;
};

} // namespace ssltut

#endif
