// vpSSLPlot: the figures of the benchmark and scenario tutorials must show the data they are given.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>
#include <visp3/core/vpException.h>
#include <visp3/core/vpImageTools.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/ssl_sim/vpSSLPlot.h>

namespace {
bool isColor(const vpRGBa &p, const vpColor &c, int tol = 40)
{
  return std::abs(p.R - c.R) < tol && std::abs(p.G - c.G) < tol && std::abs(p.B - c.B) < tol;
}

// Number of pixels of the given colour in a column band around x.
int countColor(const vpImage<vpRGBa> &I, const vpColor &c, unsigned int x0, unsigned int x1)
{
  int n = 0;
  for (unsigned int r = 0; r < I.getHeight(); ++r) {
    for (unsigned int x = x0; x < x1; ++x) {
      n += isColor(I[r][x], c) ? 1 : 0;
    }
  }
  return n;
}

// Mean row of the pixels of the given colour in a column band.
double meanRow(const vpImage<vpRGBa> &I, const vpColor &c, unsigned int x0, unsigned int x1)
{
  double sum = 0.;
  int n = 0;
  for (unsigned int r = 0; r < I.getHeight(); ++r) {
    for (unsigned int x = x0; x < x1; ++x) {
      if (isColor(I[r][x], c)) {
        sum += r;
        ++n;
      }
    }
  }
  return n ? sum / n : -1.;
}
} // namespace

TEST(Plot, RisingSeriesIsDrawnHigherOnTheRight)
{
  vpSSLPlot plot("rising", "x", "y");
  plot.addSeries("up", {0., 1., 2., 3., 4., 5.}, {0., 1., 2., 3., 4., 5.}, vpColor::red);
  vpImage<vpRGBa> I;
  plot.render(I, 600, 400);
  ASSERT_EQ(I.getWidth(), 600u);
  ASSERT_EQ(I.getHeight(), 400u);
  const double leftRow = meanRow(I, vpColor::red, 100, 160);
  const double rightRow = meanRow(I, vpColor::red, 480, 540);
  ASSERT_GT(leftRow, 0.);
  ASSERT_GT(rightRow, 0.);
  EXPECT_GT(leftRow, rightRow + 150.); // image rows grow downwards
}

TEST(Plot, NaNMakesAGapNotALine)
{
  vpSSLPlot plot;
  plot.setXRange(0., 10.);
  plot.setYRange(0., 1.);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  plot.addSeries("", {0., 1., 2., 3., 7., 8., 9., 10.}, {0.5, 0.5, 0.5, nan, nan, 0.5, 0.5, 0.5}, vpColor::blue);
  vpImage<vpRGBa> I;
  plot.render(I, 600, 300);
  // Axes span x = 62..586 for 0..10: the middle (x 4..6) must hold no blue.
  EXPECT_GT(countColor(I, vpColor::blue, 80, 160), 20);
  EXPECT_EQ(countColor(I, vpColor::blue, 280, 370), 0);
}

TEST(Plot, MismatchedSeriesAndBadRangesThrow)
{
  vpSSLPlot plot;
  EXPECT_THROW(plot.addSeries("bad", {0., 1.}, {0.}), vpException);
  EXPECT_THROW(plot.setXRange(1., 1.), vpException);
  EXPECT_THROW(plot.setYRange(0., std::numeric_limits<double>::infinity()), vpException);
  vpImage<vpRGBa> I;
  EXPECT_THROW(plot.render(I, 10, 10), vpException);
  EXPECT_THROW(vpSSLPlot::saveStacked({}, "x.png"), vpException);
}

TEST(Plot, SavesPngAndStackedPanels)
{
  vpSSLPlot a("a", "t (s)", "yaw (deg)"), b("b", "t (s)", "state");
  a.addSeries("demanded", {0., 1., 2.}, {0., 10., 5.});
  a.addVerticalLine(1.5, "target removed");
  b.addSeries("state", {0., 1., 2.}, {0., 1., 2.}, vpColor::none, vpSSLPlot::STYLE_STEPS);
  b.addHorizontalLine(1., "home");
  const std::string single = "test_plot_single.png", stacked = "test_plot_stacked.png";
  a.save(single, 400, 250);
  vpSSLPlot::saveStacked({a, b}, stacked, 400, 200);
  vpImage<vpRGBa> I;
  vpImageIo::read(I, single);
  EXPECT_EQ(I.getWidth(), 400u);
  EXPECT_EQ(I.getHeight(), 250u);
  vpImageIo::read(I, stacked);
  EXPECT_EQ(I.getHeight(), 400u);
  std::remove(single.c_str());
  std::remove(stacked.c_str());
}

TEST(Plot, UnwritableFileThrowsAndLeavesNothing)
{
  vpSSLPlot plot;
  plot.addSeries("s", {0., 1.}, {0., 1.});
  EXPECT_THROW(plot.save("/nonexistent-dir/plot.png"), vpException);
  EXPECT_THROW(plot.save("plot-without-extension"), vpException);
  std::ifstream in("plot-without-extension");
  EXPECT_FALSE(in.good());
}
