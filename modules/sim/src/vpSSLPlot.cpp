#include <visp3/ssl_sim/vpSSLPlot.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <visp3/core/vpException.h>

namespace {
// Okabe-Ito palette: distinguishable with the common colour-vision deficiencies.
const cv::Scalar kPalette[] = {cv::Scalar(178, 114, 0),   cv::Scalar(0, 94, 213),  cv::Scalar(115, 158, 0),
                               cv::Scalar(167, 121, 204), cv::Scalar(0, 159, 230), cv::Scalar(233, 180, 86),
                               cv::Scalar(66, 228, 240),  cv::Scalar(0, 0, 0)};

cv::Scalar toScalar(const vpColor &c)
{
  return cv::Scalar(c.B, c.G, c.R);
}

// Tick step of 1, 2 or 5 times a power of ten giving about \p n intervals over \p span.
double niceStep(double span, int n)
{
  const double raw = span / n;
  const double mag = std::pow(10., std::floor(std::log10(raw)));
  const double r = raw / mag;
  return (r < 1.5 ? 1. : (r < 3.5 ? 2. : (r < 7.5 ? 5. : 10.))) * mag;
}

// Widens [lo, hi] to whole ticks; a degenerate range gets a unit span so that a constant is visible.
void niceRange(double &lo, double &hi)
{
  if (!(hi > lo)) {
    const double pad = (lo == 0.) ? 1. : 0.5 * std::fabs(lo);
    lo -= pad;
    hi += pad;
  }
  const double step = niceStep(hi - lo, 6);
  lo = std::floor(lo / step + 1e-9) * step;
  hi = std::ceil(hi / step - 1e-9) * step;
}

std::string tickLabel(double v, double step)
{
  char buf[32];
  const int decimals = step >= 1. ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, std::fabs(v) < 0.5 * step * 1e-6 ? 0. : v);
  return buf;
}

void dashedLine(cv::Mat &img, cv::Point a, cv::Point b, const cv::Scalar &color)
{
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const int n = std::max(1, static_cast<int>(len / 6.));
  for (int i = 0; i < n; i += 2) {
    const cv::Point p(a.x + (b.x - a.x) * i / n, a.y + (b.y - a.y) * i / n);
    const cv::Point q(a.x + (b.x - a.x) * (i + 1) / n, a.y + (b.y - a.y) * (i + 1) / n);
    cv::line(img, p, q, color, 1, cv::LINE_AA);
  }
}

const int kFont = cv::FONT_HERSHEY_SIMPLEX;
} // namespace

vpSSLPlot::vpSSLPlot(const std::string &title, const std::string &xLabel, const std::string &yLabel)
    : m_title(title), m_xLabel(xLabel), m_yLabel(yLabel), m_xFixed(false), m_yFixed(false), m_xMin(0.), m_xMax(1.),
      m_yMin(0.), m_yMax(1.)
{
}

void vpSSLPlot::addSeries(const std::string &name, const std::vector<double> &x, const std::vector<double> &y,
                          const vpColor &color, vpSSLPlotStyle style)
{
  if (x.size() != y.size()) {
    throw vpException(vpException::dimensionError, "vpSSLPlot::addSeries: series \"%s\": %zu x values but %zu y values",
                      name.c_str(), x.size(), y.size());
  }
  vpColor c = color;
  if (c == vpColor::none) {
    const cv::Scalar &s = kPalette[m_series.size() % (sizeof(kPalette) / sizeof(kPalette[0]))];
    c = vpColor(static_cast<unsigned char>(s[2]), static_cast<unsigned char>(s[1]), static_cast<unsigned char>(s[0]));
  }
  m_series.push_back(Series{name, x, y, c, style});
}

void vpSSLPlot::addHorizontalLine(double y, const std::string &label, const vpColor &color)
{
  m_markers.push_back(Marker{false, y, label, color});
}

void vpSSLPlot::addVerticalLine(double x, const std::string &label, const vpColor &color)
{
  m_markers.push_back(Marker{true, x, label, color});
}

void vpSSLPlot::setXRange(double min, double max)
{
  if (!(std::isfinite(min) && std::isfinite(max) && min < max)) {
    throw vpException(vpException::badValue, "vpSSLPlot::setXRange: need finite min < max, got [%g, %g]", min, max);
  }
  m_xFixed = true;
  m_xMin = min;
  m_xMax = max;
}

void vpSSLPlot::setYRange(double min, double max)
{
  if (!(std::isfinite(min) && std::isfinite(max) && min < max)) {
    throw vpException(vpException::badValue, "vpSSLPlot::setYRange: need finite min < max, got [%g, %g]", min, max);
  }
  m_yFixed = true;
  m_yMin = min;
  m_yMax = max;
}

void vpSSLPlot::dataRange(double &xmin, double &xmax, double &ymin, double &ymax) const
{
  const double inf = std::numeric_limits<double>::infinity();
  xmin = ymin = inf;
  xmax = ymax = -inf;
  for (const Series &s : m_series) {
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
        xmin = std::min(xmin, s.x[i]);
        xmax = std::max(xmax, s.x[i]);
        ymin = std::min(ymin, s.y[i]);
        ymax = std::max(ymax, s.y[i]);
      }
    }
  }
  for (const Marker &m : m_markers) {
    if (!std::isfinite(m.value)) {
      continue;
    }
    double &lo = m.vertical ? xmin : ymin;
    double &hi = m.vertical ? xmax : ymax;
    lo = std::min(lo, m.value);
    hi = std::max(hi, m.value);
  }
  if (!std::isfinite(xmin)) {
    xmin = 0.;
    xmax = 1.;
  }
  if (!std::isfinite(ymin)) {
    ymin = 0.;
    ymax = 1.;
  }
  if (m_xFixed) {
    xmin = m_xMin;
    xmax = m_xMax;
  } else {
    niceRange(xmin, xmax);
  }
  if (m_yFixed) {
    ymin = m_yMin;
    ymax = m_yMax;
  } else {
    niceRange(ymin, ymax);
  }
}

void vpSSLPlot::render(vpImage<vpRGBa> &I, unsigned int width, unsigned int height) const
{
  if (width < 200 || height < 120) {
    throw vpException(vpException::badValue, "vpSSLPlot::render: image %ux%u is smaller than 200x120", width, height);
  }
  cv::Mat img(static_cast<int>(height), static_cast<int>(width), CV_8UC3, cv::Scalar(255, 255, 255));

  double xmin, xmax, ymin, ymax;
  dataRange(xmin, xmax, ymin, ymax);
  const double fs = 0.42;
  const int left = 62, right = 14, top = m_title.empty() ? 12 : 30, bottom = 44;
  const cv::Rect area(left, top, static_cast<int>(width) - left - right, static_cast<int>(height) - top - bottom);
  auto px = [&](double x) { return area.x + (x - xmin) / (xmax - xmin) * area.width; };
  auto py = [&](double y) { return area.y + area.height - (y - ymin) / (ymax - ymin) * area.height; };
  // Fixed-point coordinates (4 fractional bits) keep anti-aliased lines smooth.
  auto pt = [&](double x, double y) {
    const double cx = std::min(std::max(px(x), -1e4), 1e4), cy = std::min(std::max(py(y), -1e4), 1e4);
    return cv::Point(static_cast<int>(std::lround(cx * 16)), static_cast<int>(std::lround(cy * 16)));
  };

  const cv::Scalar grid(225, 225, 225), axis(60, 60, 60);
  const double xs = niceStep(xmax - xmin, 6), ys = niceStep(ymax - ymin, 5);
  for (double t = std::ceil(xmin / xs - 1e-9) * xs; t <= xmax + 1e-9 * xs; t += xs) {
    const int x = static_cast<int>(std::lround(px(t)));
    cv::line(img, cv::Point(x, area.y), cv::Point(x, area.y + area.height), grid, 1);
    const std::string s = tickLabel(t, xs);
    int base = 0;
    const cv::Size sz = cv::getTextSize(s, kFont, fs, 1, &base);
    cv::putText(img, s, cv::Point(x - sz.width / 2, area.y + area.height + 16), kFont, fs, axis, 1, cv::LINE_AA);
  }
  for (double t = std::ceil(ymin / ys - 1e-9) * ys; t <= ymax + 1e-9 * ys; t += ys) {
    const int y = static_cast<int>(std::lround(py(t)));
    cv::line(img, cv::Point(area.x, y), cv::Point(area.x + area.width, y), grid, 1);
    const std::string s = tickLabel(t, ys);
    int base = 0;
    const cv::Size sz = cv::getTextSize(s, kFont, fs, 1, &base);
    cv::putText(img, s, cv::Point(area.x - sz.width - 5, y + sz.height / 2), kFont, fs, axis, 1, cv::LINE_AA);
  }
  cv::rectangle(img, area, axis, 1);

  for (const Marker &m : m_markers) {
    if (!std::isfinite(m.value)) {
      continue;
    }
    const cv::Scalar c = toScalar(m.color);
    if (m.vertical) {
      const int x = static_cast<int>(std::lround(px(m.value)));
      if (x < area.x || x > area.x + area.width) {
        continue;
      }
      dashedLine(img, cv::Point(x, area.y), cv::Point(x, area.y + area.height), c);
      cv::putText(img, m.label, cv::Point(x + 3, area.y + 12), kFont, fs * 0.9, c, 1, cv::LINE_AA);
    } else {
      const int y = static_cast<int>(std::lround(py(m.value)));
      if (y < area.y || y > area.y + area.height) {
        continue;
      }
      dashedLine(img, cv::Point(area.x, y), cv::Point(area.x + area.width, y), c);
      cv::putText(img, m.label, cv::Point(area.x + 4, y - 3), kFont, fs * 0.9, c, 1, cv::LINE_AA);
    }
  }

  // Series are clipped to the axes so that a fixed range crops instead of scribbling over labels.
  cv::Mat clip = img(area);
  const cv::Point shift(-area.x * 16, -area.y * 16);
  for (const Series &s : m_series) {
    const cv::Scalar c = toScalar(s.color);
    bool havePrev = false;
    cv::Point prev;
    double prevY = 0.;
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!(std::isfinite(s.x[i]) && std::isfinite(s.y[i]))) {
        havePrev = false;
        continue;
      }
      const cv::Point p = pt(s.x[i], s.y[i]) + shift;
      if (havePrev && s.style != STYLE_MARKERS) {
        if (s.style == STYLE_STEPS) {
          const cv::Point corner = pt(s.x[i], prevY) + shift;
          cv::line(clip, prev, corner, c, 2, cv::LINE_AA, 4);
          cv::line(clip, corner, p, c, 2, cv::LINE_AA, 4);
        } else {
          cv::line(clip, prev, p, c, 2, cv::LINE_AA, 4);
        }
      }
      if (s.style == STYLE_MARKERS || s.style == STYLE_LINE_MARKERS) {
        cv::circle(clip, p, 3 * 16, c, 2, cv::LINE_AA, 4);
      }
      prev = p;
      prevY = s.y[i];
      havePrev = true;
    }
  }

  if (!m_title.empty()) {
    int base = 0;
    const cv::Size sz = cv::getTextSize(m_title, kFont, 0.55, 1, &base);
    cv::putText(img, m_title, cv::Point((static_cast<int>(width) - sz.width) / 2, 20), kFont, 0.55, axis, 1,
                cv::LINE_AA);
  }
  {
    int base = 0;
    const cv::Size sz = cv::getTextSize(m_xLabel, kFont, 0.45, 1, &base);
    cv::putText(img, m_xLabel, cv::Point(area.x + (area.width - sz.width) / 2, static_cast<int>(height) - 8), kFont,
                0.45, axis, 1, cv::LINE_AA);
  }
  if (!m_yLabel.empty()) {
    // putText cannot draw vertically: draw into a strip and rotate it.
    int base = 0;
    const cv::Size sz = cv::getTextSize(m_yLabel, kFont, 0.45, 1, &base);
    cv::Mat strip(sz.height + base + 4, sz.width + 4, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::putText(strip, m_yLabel, cv::Point(2, sz.height + 2), kFont, 0.45, axis, 1, cv::LINE_AA);
    cv::Mat rotated;
    cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
    const int y0 = std::max(0, area.y + (area.height - rotated.rows) / 2);
    const int h = std::min(rotated.rows, static_cast<int>(height) - y0);
    const int w = std::min(rotated.cols, area.x);
    rotated(cv::Rect(0, 0, w, h)).copyTo(img(cv::Rect(2, y0, w, h)));
  }

  // Legend in the top-right corner of the axes, on a white box so that it stays readable over data.
  std::vector<const Series *> named;
  for (const Series &s : m_series) {
    if (!s.name.empty()) {
      named.push_back(&s);
    }
  }
  if (!named.empty()) {
    int textWidth = 0;
    for (const Series *s : named) {
      int base = 0;
      textWidth = std::max(textWidth, cv::getTextSize(s->name, kFont, fs, 1, &base).width);
    }
    const int rowH = 16, boxW = textWidth + 34, boxH = rowH * static_cast<int>(named.size()) + 6;
    const cv::Rect box(area.x + area.width - boxW - 6, area.y + 6, boxW, boxH);
    cv::rectangle(img, box, cv::Scalar(255, 255, 255), cv::FILLED);
    cv::rectangle(img, box, cv::Scalar(180, 180, 180), 1);
    for (size_t i = 0; i < named.size(); ++i) {
      const int y = box.y + 4 + rowH * static_cast<int>(i) + rowH / 2;
      const cv::Scalar c = toScalar(named[i]->color);
      cv::line(img, cv::Point(box.x + 5, y), cv::Point(box.x + 23, y), c, 2, cv::LINE_AA);
      cv::putText(img, named[i]->name, cv::Point(box.x + 28, y + 5), kFont, fs, axis, 1, cv::LINE_AA);
    }
  }

  I.resize(height, width);
  for (unsigned int r = 0; r < height; ++r) {
    const cv::Vec3b *row = img.ptr<cv::Vec3b>(static_cast<int>(r));
    for (unsigned int c = 0; c < width; ++c) {
      I[r][c] = vpRGBa(row[c][2], row[c][1], row[c][0]);
    }
  }
}

namespace {
// Encodes to memory and renames into place so that a failed write never leaves a truncated file.
void writeImage(const std::vector<vpImage<vpRGBa>> &panels, const std::string &filename)
{
  unsigned int height = 0;
  const unsigned int width = panels.empty() ? 0 : panels.front().getWidth();
  for (const vpImage<vpRGBa> &p : panels) {
    height += p.getHeight();
  }
  cv::Mat img(static_cast<int>(height), static_cast<int>(width), CV_8UC3);
  int y = 0;
  for (const vpImage<vpRGBa> &p : panels) {
    for (unsigned int r = 0; r < p.getHeight(); ++r, ++y) {
      cv::Vec3b *row = img.ptr<cv::Vec3b>(y);
      for (unsigned int c = 0; c < width; ++c) {
        row[c] = cv::Vec3b(p[r][c].B, p[r][c].G, p[r][c].R);
      }
    }
  }
  const size_t dot = filename.find_last_of('.');
  const size_t slash = filename.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) {
    throw vpException(vpException::ioError, "%s: no image extension (.png, .jpg)", filename.c_str());
  }
  std::vector<unsigned char> bytes;
  bool ok = false;
  try {
    ok = cv::imencode(filename.substr(dot), img, bytes);
  } catch (const cv::Exception &) {
    ok = false;
  }
  if (!ok) {
    throw vpException(vpException::ioError, "%s: cannot encode an image with extension %s", filename.c_str(),
                      filename.substr(dot).c_str());
  }
  const std::string tmp = filename + ".part";
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char *>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      std::remove(tmp.c_str());
      throw vpException(vpException::ioError, "%s: cannot write the plot", filename.c_str());
    }
  }
  if (std::rename(tmp.c_str(), filename.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw vpException(vpException::ioError, "%s: cannot write the plot", filename.c_str());
  }
}
} // namespace

void vpSSLPlot::save(const std::string &filename, unsigned int width, unsigned int height) const
{
  std::vector<vpImage<vpRGBa>> panels(1);
  render(panels[0], width, height);
  writeImage(panels, filename);
}

void vpSSLPlot::saveStacked(const std::vector<vpSSLPlot> &panels, const std::string &filename, unsigned int width,
                            unsigned int panelHeight)
{
  if (panels.empty()) {
    throw vpException(vpException::badValue, "vpSSLPlot::saveStacked: %s: no panel to draw", filename.c_str());
  }
  std::vector<vpImage<vpRGBa>> images(panels.size());
  for (size_t i = 0; i < panels.size(); ++i) {
    panels[i].render(images[i], width, panelHeight);
  }
  writeImage(images, filename);
}
