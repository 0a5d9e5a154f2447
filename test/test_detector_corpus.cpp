// The independent evaluation corpus (visp_ssl_bench): its truth is exact, and the default detector keeps its
// measured recall on a fixed subset of it with no false target on the negatives.
#include <cmath>
#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl_bench/vpSSLCorpusEvaluator.h>
#include <visp3/ssl_bench/vpSSLCorpusPhotos.h>
#include <visp3/ssl_bench/vpSSLCorpusSheet.h>
#include <visp3/ssl_bench/vpSSLCorpusView.h>

#include "common/ssl_test_corpus_view.h"

namespace {
// Recall of B over the eligible views of the fixed subset below (seed 7, 70 views) with the default detector, as
// measured on the current main: B found in 26 of its 29 eligible views (90 %). It is a floor: a regression fails
// here; raise it as the detector improves.
const unsigned int kEligibleB = 29;
const unsigned int kMeasuredFoundB = 26;
// The small-landmark subset of DetectorCorpus.ShortWindowFindsSmallLandmarks, as measured on the current main.
const unsigned int kSmallViews = 150;
const unsigned int kSmallEligible = 105;
const unsigned int kSmallFoundWith = 34;
const unsigned int kSmallFoundWithout = 17;

// The sheet raster takes about a second to build: one for all the tests.
const vpSSLCorpusSheet &sslSheet()
{
  static const vpSSLCorpusSheet sheet = vpSSLCorpusSheet::sslTarget(vpSSLTarget::ssl3a3());
  return sheet;
}

// The radius over the true one of the detection within 0.15 of its radius of the truth's centre, 0 if none.
double radiusRatioNear(const vpSSLDetector &detector, const vpSSLCorpusLandmarkTruth &t)
{
  for (const vpSSLLandmark &l : detector.getLandmarks()) {
    if (std::hypot(l.u - t.u, l.v - t.v) < 0.15 * t.a) {
      return l.radius / t.a;
    }
  }
  return 0.;
}

// Sub-pixel position where the row \e v crosses \e level, searching from u = \e from towards \e to.
double crossing(const vpImage<unsigned char> &I, int v, int from, int to, double level)
{
  const int step = to > from ? 1 : -1;
  for (int u = from; u != to; u += step) {
    const double a = I[v][u], b = I[v][u + step];
    if ((a - level) * (b - level) <= 0. && a != b)
      return u + step * (a - level) / (a - b);
  }
  return std::nan("");
}
} // namespace

TEST(DetectorCorpus, FaceOnEdgesSitWhereTheTruthSays)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos none;
  vpSSLCorpusViewParams p = cleanView();
  p.cMo = tiltedOnAxis(0., 0.6, target.getLandmark(0).x);
  p.cMo[0][3] += 0.0123; // B off the principal point and off the pixel grid
  p.cMo[1][3] += 0.0071;
  vpSSLCorpusView view(target);
  view.render(p, &sheet, none);
  const vpImage<unsigned char> &I = view.getImage();
  const vpSSLCorpusLandmarkTruth &B = view.getTruth()[0];
  ASSERT_TRUE(B.wholeInFrame);
  // Face-on, the circle's image is a circle centred on the projected centre.
  EXPECT_NEAR(B.a, 800. * 0.1 / 0.6, 1e-9);
  EXPECT_NEAR(B.b, B.a, 1e-9);
  EXPECT_NEAR(B.ellipseU, B.u, 1e-9);
  EXPECT_NEAR(B.ellipseV, B.v, 1e-9);

  // The outer edge (ink inside, paper outside) crosses the half level where the true circle crosses the row and
  // the column nearest the centre: area-integrated edges put it there within 0.1 px.
  const int vr = static_cast<int>(std::lround(B.v)), uc = static_cast<int>(std::lround(B.u));
  const double paper = I[vr][static_cast<int>(B.u + 1.15 * B.a)], ink = I[vr][static_cast<int>(B.u + 0.85 * B.a)];
  ASSERT_GT(paper - ink, 150.);
  const double half = 0.5 * (paper + ink);
  const double dv = vr - B.v, du = uc - B.u;
  const double reachU = std::sqrt(B.a * B.a - dv * dv), reachV = std::sqrt(B.a * B.a - du * du);
  const int from = static_cast<int>(0.85 * B.a), to = static_cast<int>(1.15 * B.a);
  EXPECT_NEAR(crossing(I, vr, uc + from, uc + to, half), B.u + reachU, 0.1);
  EXPECT_NEAR(crossing(I, vr, uc - from, uc - to, half), B.u - reachU, 0.1);
  vpImage<unsigned char> T; // the transpose, to read columns as rows
  T.resize(I.getWidth(), I.getHeight());
  for (unsigned int i = 0; i < I.getHeight(); ++i)
    for (unsigned int j = 0; j < I.getWidth(); ++j)
      T[j][i] = I[i][j];
  const int vc = static_cast<int>(std::lround(B.v));
  EXPECT_NEAR(crossing(T, uc, vc + from, vc + to, half), B.v + reachV, 0.1);
  EXPECT_NEAR(crossing(T, uc, vc - from, vc - to, half), B.v - reachV, 0.1);
}

TEST(DetectorCorpus, RingsSitWhereTheHomographySaysUnderStrongTilt)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos none;
  for (double tiltDeg : {0., 35., 60.}) {
    vpSSLCorpusViewParams p = cleanView();
    p.supersampling = 4;
    p.cMo = tiltedOnAxis(tiltDeg * M_PI / 180., 0.5, target.getLandmark(0).x);
    vpSSLCorpusView view(target);
    view.render(p, &sheet, none);
    const vpImage<unsigned char> &I = view.getImage();
    const cv::Matx33d H = vpSSLCorpusView::homography(p);
    // Mid-ring points of the printed square wave (rho = 0.85, 0.6, 0.42: ink, paper, ink) and the margin (1.1),
    // in 16 directions, through the homography: dark and bright where the print says.
    const vpSSLTargetLandmark &L = target.getLandmark(0);
    int checked = 0;
    for (double rho : {0.85, 0.6, 0.42, 1.1}) {
      const bool inked = vpSSLCorpusSheet::sslPaper(target, L.x + rho * L.radius, L.y) < 0.5;
      for (int k = 0; k < 16; ++k) {
        const double t = 2. * M_PI * k / 16.;
        const cv::Vec3d q = H * cv::Vec3d(L.x + rho * L.radius * std::cos(t), L.y + rho * L.radius * std::sin(t), 1.);
        const int u = static_cast<int>(std::lround(q[0] / q[2])), v = static_cast<int>(std::lround(q[1] / q[2]));
        ASSERT_TRUE(u >= 0 && v >= 0 && u < 640 && v < 480);
        if (inked)
          EXPECT_LT(I[v][u], 60) << "tilt " << tiltDeg << " rho " << rho << " direction " << k;
        else
          EXPECT_GT(I[v][u], 150) << "tilt " << tiltDeg << " rho " << rho << " direction " << k;
        ++checked;
      }
    }
    EXPECT_EQ(checked, 64);
  }
}

TEST(DetectorCorpus, TruthCentreIsNotTheEllipseCentreUnderPerspective)
{
  // Optical axis through B's centre, the sheet tilted about X: by symmetry the ellipse's v-extremes are the
  // images of the circle's points (0, +-R), so its centre lies at v0 - f R^2 sin cos / (D^2 - R^2 sin^2), not at
  // the projected centre v0; its v semi-axis is f R cos D / (D^2 - R^2 sin^2).
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const double f = 800., R = target.getLandmark(0).radius, D = 0.35;
  for (double tiltDeg : {0., 30., 60.}) {
    vpSSLCorpusViewParams p = cleanView();
    const double th = tiltDeg * M_PI / 180., s = std::sin(th), c = std::cos(th);
    p.cMo = tiltedOnAxis(th, D, target.getLandmark(0).x);
    const vpSSLCorpusLandmarkTruth B = vpSSLCorpusView::geometry(target, p)[0];
    ASSERT_TRUE(B.isEllipse);
    EXPECT_NEAR(B.u, p.camera.u0, 1e-9);
    EXPECT_NEAR(B.v, p.camera.v0, 1e-9);
    EXPECT_NEAR(B.ellipseU, p.camera.u0, 1e-6);
    const double offset = -f * R * R * s * c / (D * D - R * R * s * s);
    EXPECT_NEAR(B.ellipseV - B.v, offset, 1e-6);
    EXPECT_NEAR(B.b, f * R * c * D / (D * D - R * R * s * s), 1e-6);
    if (tiltDeg == 60.)
      EXPECT_GT(std::fabs(B.ellipseV - B.v), 25.); // about 30 px: the detector must not report the ellipse centre
    // Every point of the circle projects onto the truth's ellipse.
    const cv::Matx33d H = vpSSLCorpusView::homography(p);
    for (int k = 0; k < 32; ++k) {
      const double t = 2. * M_PI * k / 32.;
      const cv::Vec3d q = H * cv::Vec3d(target.getLandmark(0).x + R * std::cos(t), R * std::sin(t), 1.);
      const double du = q[0] / q[2] - B.ellipseU, dv = q[1] / q[2] - B.ellipseV;
      const double x = du * std::cos(B.theta) + dv * std::sin(B.theta),
                   y = -du * std::sin(B.theta) + dv * std::cos(B.theta);
      EXPECT_NEAR(x * x / (B.a * B.a) + y * y / (B.b * B.b), 1., 1e-9);
    }
  }
}

TEST(DetectorCorpus, SameSeedSameView)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet sheet = vpSSLCorpusSheet::sslTarget(target, 2000.); // coarse: speed, not accuracy, here
  vpSSLCorpusPhotos photos;
  photos.load();
  vpSSLCorpusView a(target), b(target);
  a.render(vpSSLCorpusView::draw(target, photos, 3, 5, true), &sheet, photos);
  b.render(vpSSLCorpusView::draw(target, photos, 3, 5, true), &sheet, photos);
  vpImage<unsigned char> first = a.getImage(), second = b.getImage();
  EXPECT_TRUE(first == second);
  b.render(vpSSLCorpusView::draw(target, photos, 3, 6, true), &sheet, photos);
  second = b.getImage();
  EXPECT_FALSE(first == second);
}

TEST(DetectorCorpus, RecallTableByMinorSemiAxisOverBlur)
{
  // Three eligible B: b / sigma = 5 (found), 50 (missed) and no blur at all (found, in the top bin), the last seen
  // 70 degrees off its normal, which the second table leaves out.
  vpSSLCorpusEvaluator evaluator;
  const double blurs[3] = {2., 0.2, 0.};
  const bool found[3] = {true, false, true};
  const double angles[3] = {30., 60., 70.};
  for (int k = 0; k < 3; ++k) {
    vpSSLCorpusViewResult r;
    r.index = static_cast<unsigned int>(k);
    vpSSLCorpusLandmarkTruth t;
    t.name = "B";
    t.a = 12.;
    t.b = 10.;
    t.wholeInFrame = t.centreInFrame = t.isEllipse = true;
    t.contrastOverNoise = 10.;
    t.blurSigma = blurs[k];
    t.viewAngle = angles[k];
    r.truth.push_back(t);
    vpSSLCorpusLandmarkResult res;
    res.found = found[k];
    r.results.push_back(res);
    evaluator.add(r);
  }
  std::ostringstream os;
  evaluator.printTables(os);
  const std::string md = os.str();
  // The rows of the table headed exactly by \e title (empty if there is none).
  auto tableRows = [&md](const std::string &title) {
    const size_t table = md.find("#### Recall by " + title + "\n");
    if (table == std::string::npos)
      return std::string();
    const size_t next = md.find("####", table + 4);
    return md.substr(table, next == std::string::npos ? std::string::npos : next - table);
  };
  const std::string rows = tableRows("minor semi-axis / blur sigma");
  ASSERT_FALSE(rows.empty()) << md;
  EXPECT_NE(rows.find("| 0-4 | - | - | - |"), std::string::npos) << rows;
  EXPECT_NE(rows.find("| 4-8 | 100.0 % (1) | - | - |"), std::string::npos) << rows;
  EXPECT_NE(rows.find("| 16-32 | - | - | - |"), std::string::npos) << rows;
  EXPECT_NE(rows.find("| 32+ | 50.0 % (2) | - | - |"), std::string::npos) << rows;
  const std::string near = tableRows("minor semi-axis / blur sigma, view angle <= 60 deg");
  ASSERT_FALSE(near.empty()) << md;
  EXPECT_NE(near.find("| 4-8 | 100.0 % (1) | - | - |"), std::string::npos) << near;
  EXPECT_NE(near.find("| 32+ | 0.0 % (1) | - | - |"), std::string::npos) << near;
}

TEST(DetectorCorpus, DefaultDetectorKeepsItsRecallAndFindsNoTargetInNegatives)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the measured figures include photo backgrounds)";
  vpSSLDetector detector(target);
  vpSSLCorpusView view(target);
  vpSSLCorpusEvaluator evaluator;
  const unsigned int nbViews = 70, nbNegatives = 20;
  for (unsigned int i = 0; i < nbViews + nbNegatives; ++i) {
    const bool positive = i < nbViews;
    vpSSLCorpusViewResult r;
    r.index = positive ? i : i - nbViews;
    r.params = vpSSLCorpusView::draw(target, photos, 7, r.index, positive);
    view.render(r.params, &sheet, photos);
    r.truth = view.getTruth();
    detector.detect(view.getImage());
    vpSSLCorpusEvaluator::match(detector, r);
    evaluator.add(r);
  }
  unsigned int n = 0;
  const double recallB = evaluator.recall("B", n);
  EXPECT_EQ(n, kEligibleB) << "the subset changed: re-measure the floor";
  EXPECT_GE(recallB * n + 1e-9, static_cast<double>(kMeasuredFoundB)) << "B found in " << recallB * n << " of " << n;
  unsigned int nNeg = 0;
  EXPECT_EQ(evaluator.falseTargetsOnNegatives(nNeg), 0u);
  EXPECT_EQ(nNeg, nbNegatives);
}

// Landmarks of 8 to 12 px of radius (the first 150 views of seed 11 that hold one whole in the frame): the w = 40 map
// gives no peak at the centre of most, the short window of a full search does (vpSSLDetector::setShortWindow()). As
// measured on the current main: 34 of the 105 eligible found, 17 without the short window (the ring reading, not the
// peaks, loses the others: doc/detector.md).
TEST(DetectorCorpus, ShortWindowFindsSmallLandmarks)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the measured figures include photo backgrounds)";
  vpSSLDetector withShort(target), withoutShort(target);
  withoutShort.setShortWindow(0);
  EXPECT_EQ(withShort.getShortWindow(), 10u);
  vpSSLCorpusView view(target);
  unsigned int eligible = 0, foundWith = 0, foundWithout = 0, rendered = 0;
  for (uint64_t index = 0; rendered < kSmallViews && index < 20000; ++index) {
    const vpSSLCorpusViewParams p = vpSSLCorpusView::draw(target, photos, 11, index, true);
    bool small = false;
    for (const vpSSLCorpusLandmarkTruth &t : vpSSLCorpusView::geometry(target, p)) {
      small = small || (t.wholeInFrame && t.a >= 8. && t.a < 12.);
    }
    if (!small) {
      continue;
    }
    ++rendered;
    view.render(p, &sheet, photos);
    withShort.detect(view.getImage());
    withoutShort.detect(view.getImage());
    for (const vpSSLCorpusLandmarkTruth &t : view.getTruth()) {
      if (!t.eligible() || t.a >= 12.) {
        continue;
      }
      ++eligible;
      auto found = [&t](const vpSSLDetector &d) {
        for (const vpSSLLandmark &l : d.getLandmarks()) {
          if (std::hypot(l.u - t.u, l.v - t.v) < 0.15 * t.a) {
            return 1u;
          }
        }
        return 0u;
      };
      foundWith += found(withShort);
      foundWithout += found(withoutShort);
    }
  }
  std::cout << "small landmarks: " << eligible << " eligible in " << rendered << " views, found " << foundWith
            << " with the short window, " << foundWithout << " without" << std::endl;
  EXPECT_EQ(eligible, kSmallEligible) << "the subset changed: re-measure the floors";
  EXPECT_GE(foundWith, kSmallFoundWith);
  EXPECT_LE(foundWithout, kSmallFoundWithout);
}

// Two views of the corpus of seed 1 (doc/detector.md's tables) whose B, 15 and 11 px in radius (the root of its
// semi-axes' product) and seen 73 and 64 degrees off its normal, gets its peak from the short window on the image's
// half only: as measured, neither is found with the maps of w = 40 and w = 10 on the image alone.
TEST(DetectorCorpus, HalfImageWindowFindsLandmarksBetweenTheOtherWindows)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the views are drawn with photo backgrounds possible)";
  vpSSLDetector detector(target);
  vpSSLCorpusView view(target);
  for (uint64_t index : {424u, 954u}) {
    view.render(vpSSLCorpusView::draw(target, photos, 1, index, true), &sheet, photos);
    const vpSSLCorpusLandmarkTruth &b = view.getTruth()[0];
    ASSERT_EQ(b.name, "B");
    ASSERT_TRUE(b.eligible()) << "view " << index << ": the corpus changed";
    detector.detect(view.getImage());
    bool found = false;
    for (const vpSSLLandmark &l : detector.getLandmarks()) {
      found = found || std::hypot(l.u - b.u, l.v - b.v) < 0.15 * b.a;
    }
    EXPECT_TRUE(found) << "view " << index << ": B (" << b.a << " x " << b.b << " px) not found";
  }
}

// The all-around reader's budget (vpSSLDetector::setAllAroundBudget(), doc/detector.md "Its budget"), both ways. Two B
// of seed 1 of the corpus, 13 and 14 px, 5 and 7 noise sigmas of contrast, on flat noisy water whose noise peaks the
// rays give up on and the reader reads in vain first: their reading is the 30th and the 37th of their frame, so the
// default budget of 24 misses them and 48 reads them within 10 % of their radius. Two negatives, seeds 6 and 13, where
// 48 reads a false landmark past the 24th candidate, a false target the default does not give.
TEST(DetectorCorpus, AllAroundBudgetTradesFaintLandmarksForFalseReadings)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the views are drawn with photo backgrounds possible)";
  vpSSLDetector byDefault(target), wider(target);
  EXPECT_EQ(byDefault.getAllAroundBudget(), 24u);
  wider.setAllAroundBudget(48);
  EXPECT_EQ(wider.getAllAroundBudget(), 48u);
  vpSSLCorpusView view(target);
  for (uint64_t index : {816u, 991u}) {
    view.render(vpSSLCorpusView::draw(target, photos, 1, index, true), &sheet, photos);
    const vpSSLCorpusLandmarkTruth &b = view.getTruth()[0];
    ASSERT_EQ(b.name, "B");
    ASSERT_TRUE(b.eligible()) << "view " << index << ": the corpus changed";
    byDefault.detect(view.getImage());
    wider.detect(view.getImage());
    EXPECT_GT(std::fabs(radiusRatioNear(byDefault, b) - 1.), 0.1) << "view " << index << ": B read with 24";
    EXPECT_LE(std::fabs(radiusRatioNear(wider, b) - 1.), 0.1)
        << "view " << index << ": B (" << b.a << " x " << b.b << " px) not read with 48";
  }
  for (const auto &n : {std::make_pair<uint64_t, uint64_t>(6, 220), std::make_pair<uint64_t, uint64_t>(13, 16)}) {
    view.render(vpSSLCorpusView::draw(target, photos, n.first, n.second, false), &sheet, photos);
    byDefault.detect(view.getImage());
    wider.detect(view.getImage());
    EXPECT_FALSE(byDefault.getTargetMatch().found) << "seed " << n.first << ", negative " << n.second;
    EXPECT_TRUE(wider.getTargetMatch().found) << "seed " << n.first << ", negative " << n.second;
  }
}

// A budget of 0 leaves the rays alone: a B of seed 1 of the corpus, 33 px seen 74 degrees off its normal, which the
// rays give up on and the all-around reader reads, is not read.
TEST(DetectorCorpus, AllAroundBudgetOfZeroLeavesTheRaysAlone)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the views are drawn with photo backgrounds possible)";
  vpSSLDetector byDefault(target), raysOnly(target);
  raysOnly.setAllAroundBudget(0);
  vpSSLCorpusView view(target);
  view.render(vpSSLCorpusView::draw(target, photos, 1, 2, true), &sheet, photos);
  const vpSSLCorpusLandmarkTruth &b = view.getTruth()[0];
  ASSERT_EQ(b.name, "B");
  byDefault.detect(view.getImage());
  raysOnly.detect(view.getImage());
  EXPECT_GT(radiusRatioNear(byDefault, b), 0.);
  EXPECT_EQ(radiusRatioNear(raysOnly, b), 0.);
}

// Four negatives of the corpora of seeds 2, 5, 6 and 9 (doc/detector.md) where a bull's-eye of the `rings`
// surroundings, 19 to 42 px, passes for a lone B without the equal-ring check (a false target); the check, on by
// default (vpSSLDetector::setEqualRingCheck()), turns each away.
TEST(DetectorCorpus, EqualRingCheckTurnsAwayBullsEyes)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the views are drawn with photo backgrounds possible)";
  vpSSLDetector byDefault(target), unchecked(target);
  unchecked.setEqualRingCheck(false);
  EXPECT_TRUE(byDefault.getEqualRingCheck());
  EXPECT_FALSE(unchecked.getEqualRingCheck());
  vpSSLCorpusView view(target);
  const std::pair<uint64_t, uint64_t> negatives[] = {{2, 11}, {5, 28}, {6, 268}, {9, 215}};
  for (const auto &n : negatives) {
    const vpSSLCorpusViewParams p = vpSSLCorpusView::draw(target, photos, n.first, n.second, false);
    ASSERT_EQ(p.background, vpSSLCorpusViewParams::RINGS) << "seed " << n.first << ": the corpus changed";
    view.render(p, &sheet, photos);
    unchecked.detect(view.getImage());
    byDefault.detect(view.getImage());
    EXPECT_TRUE(unchecked.getTargetMatch().found) << "seed " << n.first << ", negative " << n.second;
    EXPECT_FALSE(byDefault.getTargetMatch().found) << "seed " << n.first << ", negative " << n.second;
  }
}

namespace {
// Renders each negatives (seed, index) of the corpus and expects a target from the detector with its bull's-eye checks
// off (setEqualRingCheck(false)), none by default, and with \e noLandmark no landmark either.
void expectChecksTurnAway(const std::vector<std::pair<uint64_t, uint64_t>> &negatives, bool noLandmark)
{
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the negatives are drawn with photo backgrounds possible)";
  vpSSLDetector byDefault(target), unchecked(target);
  byDefault.setNbThreads(1);
  unchecked.setNbThreads(1);
  unchecked.setEqualRingCheck(false);
  vpSSLCorpusView view(target);
  for (const auto &n : negatives) {
    view.render(vpSSLCorpusView::draw(target, photos, n.first, n.second, false), &sheet, photos);
    unchecked.detect(view.getImage());
    byDefault.detect(view.getImage());
    EXPECT_TRUE(unchecked.getTargetMatch().found) << "seed " << n.first << ", negative " << n.second;
    if (noLandmark) {
      EXPECT_TRUE(byDefault.getLandmarks().empty()) << "seed " << n.first << ", negative " << n.second;
    }
    EXPECT_FALSE(byDefault.getTargetMatch().found) << "seed " << n.first << ", negative " << n.second;
  }
}
} // namespace

// Four negatives of the corpora of seeds 8, 9 and 10 (doc/detector.md) where round clutter of 10 to 20 px passes
// both the similarity and the equal-ring tests and is reported as a lone B: bull's-eyes of the `rings` surroundings, a
// pattern of a photograph, a dark speck in turbid water. Each has its centre disc darker than its outer black ring
// (vpSSLCentreTone); a landmark's is two thirds white. The check, on with the equal-ring check, turns each away.
TEST(DetectorCorpus, CentreToneTurnsAwayDarkCentredClutter)
{
  expectChecksTurnAway({{8, 211}, {9, 17}, {9, 266}, {10, 252}}, true);
}

// Negatives of the corpus where bull's-eyes of 11 to 35 px, rings of one width ending in a dark dot, pass for landmarks
// (a lighter centre disc than the outer black ring, so the centre tone alone keeps them) and make a false target with
// the bull's-eye checks off; with them on (the default), the light ring across the band about p^2 R turns them away
// and no target is found.
TEST(DetectorCorpus, CoreRiseTurnsAwayBullsEyesEndingInADarkDot)
{
  expectChecksTurnAway({{9, 229}, {10, 9}, {10, 98}, {11, 111}, {13, 4}}, false);
}

TEST(DetectorCorpus, BlurredRingModelFindsFaintBlurredB)
{
  // doc/detector.md: six views of seed 1 whose B (11 to 38 px, blurred, a few grey levels of ring contrast) the
  // detector misses without the blurred-ring model; with it, on by default, each is found (centre within 0.15 of
  // its radius, the corpus's criterion) with its radius within 10 %.
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the views are drawn with photo backgrounds possible)";
  vpSSLDetector without(target), model(target);
  without.setNbThreads(1);
  model.setNbThreads(1);
  without.setBlurredRingModel(false);
  EXPECT_FALSE(without.getBlurredRingModel());
  EXPECT_TRUE(model.getBlurredRingModel());
  vpSSLCorpusView view(target);
  for (uint64_t index : {50u, 447u, 736u, 883u, 892u, 929u}) {
    view.render(vpSSLCorpusView::draw(target, photos, 1, index, true), &sheet, photos);
    const vpSSLCorpusLandmarkTruth &B = view.getTruth()[0];
    ASSERT_TRUE(B.eligible()) << "view " << index << ": the corpus changed";
    auto found = [&](const vpSSLDetector &d, double &radius) {
      for (const vpSSLLandmark &l : d.getLandmarks()) {
        if (std::hypot(l.u - B.u, l.v - B.v) < 0.15 * B.a) {
          radius = l.radius;
          return true;
        }
      }
      return false;
    };
    without.detect(view.getImage());
    model.detect(view.getImage());
    double r = 0.;
    EXPECT_FALSE(found(without, r)) << "view " << index;
    ASSERT_TRUE(found(model, r)) << "view " << index << ", B " << B.a << " px";
    EXPECT_NEAR(r / B.a, 1., 0.1) << "view " << index;
  }
}

TEST(DetectorCorpus, TargetCompletionReadsTheLandmarksBesideB)
{
  // doc/detector.md: views of seed 1 whose B the detector reads but whose S1 and S2 it misses without the target
  // completion (their peaks under those of the surroundings, or their rings, 3.3 to 6.5 noise sigmas of contrast,
  // passing no test alone); with it, on by default, each is found (centre within 0.15 of its radius) with its radius
  // within 10 %. In views 172 and 868 B itself is read at twice its radius without it (the paper and the dark water
  // past its outer ring read as one more ring, its small landmarks inside the disc read) and at its size with it.
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the views are drawn with photo backgrounds possible)";
  vpSSLDetector without(target), completion(target);
  without.setNbThreads(1);
  completion.setNbThreads(1);
  without.setTargetCompletion(false);
  EXPECT_FALSE(without.getTargetCompletion());
  EXPECT_TRUE(completion.getTargetCompletion());
  vpSSLCorpusView view(target);
  for (uint64_t index : {171u, 172u, 584u, 868u, 918u}) {
    view.render(vpSSLCorpusView::draw(target, photos, 1, index, true), &sheet, photos);
    auto find = [&](const vpSSLDetector &d, const vpSSLCorpusLandmarkTruth &t, double &radius) {
      for (const vpSSLLandmark &l : d.getLandmarks()) {
        if (std::hypot(l.u - t.u, l.v - t.v) < 0.15 * t.a) {
          radius = l.radius;
          return true;
        }
      }
      return false;
    };
    without.detect(view.getImage());
    completion.detect(view.getImage());
    for (const vpSSLCorpusLandmarkTruth &t : view.getTruth()) {
      const std::string what = "view " + std::to_string(index) + " " + t.name;
      ASSERT_TRUE(t.eligible()) << what << ": the corpus changed";
      double r = 0.;
      if (t.name == "B") {
        ASSERT_TRUE(find(without, t, r)) << what;
        if (index == 172u || index == 868u) {
          EXPECT_GT(r / t.a, 1.5) << what;
        }
      } else {
        EXPECT_FALSE(find(without, t, r)) << what;
      }
      ASSERT_TRUE(find(completion, t, r)) << what;
      EXPECT_NEAR(r / t.a, 1., 0.1) << what;
    }
    EXPECT_EQ(completion.getTargetMatch().nbMatched, 3u) << "view " << index;
  }
}

TEST(DetectorCorpus, QuarterImageFindsLargeFaintBlurredLandmarks)
{
  // doc/detector.md: a faint B (paper 0.6, ink 0.45) of 90 and 120 px, face-on and 50 degrees off its normal, blurred
  // by 2.5 and 3 px, gives no peak at its centre that w = 40 or the short window reads: its narrow inner rings are
  // wiped out and its outer ones wider than those windows. The quarter image's window (80 px in image pixels) gives
  // one; the default detector then reads 7 of the 8 within 10 % of their radius (none without that window).
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos; // no photo: the views below have none
  vpSSLDetector detector(target);
  detector.setNbThreads(1);
  vpSSLCorpusView view(target);
  unsigned int found = 0, total = 0;
  for (double radius : {90., 120.}) {
    for (double tilt : {0., 50.}) {
      for (double sigma : {2.5, 3.}) {
        vpSSLCorpusViewParams p = cleanView();
        p.cMo = tiltedOnAxis(tilt * M_PI / 180., p.camera.px * 0.1 / radius, target.getLandmark(0).x);
        p.gaussSigma = sigma;
        p.noiseGain = 1e-3;
        p.readNoise = 0.005;
        p.paper = 0.6;
        p.ink = 0.45;
        view.render(p, &sheet, photos);
        const vpSSLCorpusLandmarkTruth &b = view.getTruth()[0];
        ASSERT_EQ(b.name, "B");
        detector.detect(view.getImage());
        found += std::fabs(radiusRatioNear(detector, b) - 1.) <= 0.1 ? 1 : 0;
        ++total;
      }
    }
  }
  EXPECT_EQ(total, 8u);
  EXPECT_GE(found, 7u);
}

TEST(DetectorCorpus, TargetCompletionReadsBAtItsSizeBesideTheOthers)
{
  // doc/detector.md: views of seed 1 whose three landmarks the detector finds but whose B it reads one ring pair off:
  // at twice its radius (views 228 and 374: the paper and the surroundings past its outer ring read as one more ring),
  // or at its inner copy, of S1's and S2's size (views 90 and 614, its outer ring cut by the frame's edge; 531, 750
  // and 814, where the match then takes S1 or S2 for B). The target completion reads B again at the size that puts S1
  // and S2 where they are, and keeps it only where its outer rings are there: each landmark is then found within 10 %
  // of its radius and the target match holds all three. In view 299 (B cut, read at an inner copy beside S1 and S2, the
  // three of one size in an equilateral triangle) no landmark is read at twice its size.
  const vpSSLTarget target = vpSSLTarget::ssl3a3();
  const vpSSLCorpusSheet &sheet = sslSheet();
  vpSSLCorpusPhotos photos;
  if (photos.load() == 0)
    GTEST_SKIP() << photos.getMessage() << " (the views are drawn with photo backgrounds possible)";
  vpSSLDetector detector(target);
  detector.setNbThreads(1);
  vpSSLCorpusView view(target);
  for (uint64_t index : {228u, 374u, 90u, 614u, 531u, 750u, 814u}) {
    view.render(vpSSLCorpusView::draw(target, photos, 1, index, true), &sheet, photos);
    detector.detect(view.getImage());
    for (const vpSSLCorpusLandmarkTruth &t : view.getTruth()) {
      EXPECT_NEAR(radiusRatioNear(detector, t), 1., 0.1) << "view " << index << " " << t.name;
    }
    EXPECT_EQ(detector.getTargetMatch().nbMatched, 3u) << "view " << index;
  }
  view.render(vpSSLCorpusView::draw(target, photos, 1, 299u, true), &sheet, photos);
  detector.detect(view.getImage());
  for (const vpSSLCorpusLandmarkTruth &t : view.getTruth()) {
    if (t.name != "B") {
      EXPECT_NEAR(radiusRatioNear(detector, t), 1., 0.1) << "view 299 " << t.name;
    }
  }
}
