/*!
  \file vpSSLPlot.h
  \brief Offline line plots written to PNG, for benchmark and scenario reports.
*/
#ifndef VP_SSL_PLOT_H
#define VP_SSL_PLOT_H

#include <string>
#include <vector>

#include <visp3/core/vpColor.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLPlot
  \ingroup group_ssl_sim
  \brief One panel of x-y series with axes, ticks, labels and a legend, drawn without a display.

  ViSP's vpPlot draws live into a window; benchmark runs and closed-loop scenarios run headless on CI
  machines and must leave their figures behind as files. A panel holds any number of series; NaN
  values break a line (a gap, e.g. while the target is out of view) instead of drawing through it.
  Several panels sharing a time axis go into one image with saveStacked(), like the paper's Fig. 7.

  \code
  vpSSLPlot plot("Detection rate vs range", "range (m)", "detection rate");
  plot.addSeries("SSL", range, rateSsl);
  plot.addSeries("AprilTag", range, rateTag, vpColor::red, vpSSLPlot::STYLE_LINE_MARKERS);
  plot.setYRange(0., 1.);
  plot.save("rate.png");
  \endcode
*/
class VISP_SSL_EXPORT vpSSLPlot
{
public:
  //! How a series is drawn.
  enum vpSSLPlotStyle
  {
    STYLE_LINE,         ///< Straight segments between consecutive points.
    STYLE_MARKERS,      ///< A small circle at each point, no line.
    STYLE_LINE_MARKERS, ///< Both.
    STYLE_STEPS         ///< Held until the next point: states, counts, switches.
  };

  /*!
    \param title Panel title, drawn above the axes (may be empty).
    \param xLabel Label of the horizontal axis, with its unit.
    \param yLabel Label of the vertical axis, with its unit.
  */
  explicit vpSSLPlot(const std::string &title = "", const std::string &xLabel = "", const std::string &yLabel = "");

  /*!
    Adds a series. \p x and \p y must have the same size (else vpException::dimensionError naming the
    series). Points where x or y is not finite are gaps.
    \param name Legend entry (an empty name is left out of the legend).
    \param x Horizontal coordinates of the points.
    \param y Vertical coordinates of the points.
    \param color vpColor::none picks the next colour of a palette readable by colour-blind readers.
    \param style How the points are drawn (vpSSLPlotStyle).
  */
  void addSeries(const std::string &name, const std::vector<double> &x, const std::vector<double> &y,
                 const vpColor &color = vpColor::none, vpSSLPlotStyle style = STYLE_LINE);
  //! Dashed horizontal reference line (a set point, a threshold) with an optional label.
  void addHorizontalLine(double y, const std::string &label = "", const vpColor &color = vpColor::darkGray);
  //! Dashed vertical marker line (an event: target removed, collision) with an optional label.
  void addVerticalLine(double x, const std::string &label = "", const vpColor &color = vpColor::darkGray);

  //! Fixes the horizontal range (default: the data's, rounded to ticks). Requires min < max.
  void setXRange(double min, double max);
  //! Fixes the vertical range (default: the data's, rounded to ticks). Requires min < max.
  void setYRange(double min, double max);
  //! Sets the title.
  void setTitle(const std::string &title) { m_title = title; }

  //! Number of series added.
  size_t getNbSeries() const { return m_series.size(); }

  /*!
    Draws the panel into \p I, resized to \p width x \p height (at least 200 x 120, else
    vpException::badValue).
  */
  void render(vpImage<vpRGBa> &I, unsigned int width = 800, unsigned int height = 450) const;

  /*!
    Writes the panel as an image file (PNG by extension). Throws vpException::ioError naming the
    file when it cannot be written; an existing file is replaced only by a complete image.
  */
  void save(const std::string &filename, unsigned int width = 800, unsigned int height = 450) const;

  /*!
    Writes \p panels one above the other in a single image, each \p panelHeight pixels high. Panels
    meant to share a time axis should be given the same setXRange().
  */
  static void saveStacked(const std::vector<vpSSLPlot> &panels, const std::string &filename, unsigned int width = 800,
                          unsigned int panelHeight = 220);

private:
  struct Series
  {
    std::string name;
    std::vector<double> x, y;
    vpColor color;
    vpSSLPlotStyle style;
  };
  struct Marker
  {
    bool vertical;
    double value;
    std::string label;
    vpColor color;
  };

  void dataRange(double &xmin, double &xmax, double &ymin, double &ymax) const;

  std::string m_title, m_xLabel, m_yLabel;
  std::vector<Series> m_series;
  std::vector<Marker> m_markers;
  bool m_xFixed, m_yFixed;
  double m_xMin, m_xMax, m_yMin, m_yMax;
};

#endif
