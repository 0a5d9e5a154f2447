/*
  The printed pattern (paper Eq. 1 and 4) and the target model: the built-in ssl3-a3 matches its
  table of doc/target-ssl3-a3.md, target files read back what was written, and every bad file is rejected
  with a message naming file, line and field.
*/
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>

#include <visp3/core/vpException.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/ssl/vpSSLPattern.h>
#include <visp3/ssl/vpSSLTarget.h>

namespace {
const double kSpecTol = 1e-6; // doc/target-ssl3-a3.md gives the geometry to the micrometre

std::string dataFile(const std::string &name)
{
  return std::string(VISP_SSL_DATA_DIR) + "/targets/" + name;
}

// A scratch directory per test, so that messages can be checked for the bare file name "t.txt".
class TargetFileTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const ::testing::TestInfo *info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = std::filesystem::temp_directory_path() /
            ("visp_ssl_test_target_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(m_dir);
  }
  void TearDown() override
  {
    std::error_code ec;
    std::filesystem::remove_all(m_dir, ec);
  }

  std::string write(const std::string &text, const std::string &name = "t.txt")
  {
    std::string path = (m_dir / name).string();
    std::ofstream(path) << text;
    return path;
  }

  // Loads `text` and returns the error message; fails the test if it loads or throws the wrong code.
  std::string loadError(const std::string &text, int code = vpException::badValue)
  {
    std::string path = write(text);
    try {
      vpSSLTarget::load(path);
    } catch (const vpException &e) {
      EXPECT_EQ(e.getCode(), code) << e.getStringMessage();
      return e.getStringMessage();
    }
    ADD_FAILURE() << "file loaded without error:\n" << text;
    return "";
  }

  std::filesystem::path m_dir;
};

const std::string kHeader = "# test target\nname t\nsheet 0.420 0.297 -0.051 0.0\n";

void expectSameTarget(const vpSSLTarget &a, const vpSSLTarget &b, double tol)
{
  EXPECT_EQ(a.getName(), b.getName());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    const vpSSLTargetLandmark &la = a.getLandmark(i), &lb = b.getLandmark(i);
    EXPECT_EQ(la.name, lb.name);
    EXPECT_NEAR(la.x, lb.x, tol) << la.name;
    EXPECT_NEAR(la.y, lb.y, tol) << la.name;
    EXPECT_NEAR(la.z, lb.z, tol) << la.name;
    EXPECT_NEAR(la.radius, lb.radius, tol) << la.name;
    EXPECT_NEAR(la.p, lb.p, tol) << la.name;
  }
  EXPECT_NEAR(a.getSheetWidth(), b.getSheetWidth(), tol);
  EXPECT_NEAR(a.getSheetHeight(), b.getSheetHeight(), tol);
  EXPECT_NEAR(a.getSheetCenterX(), b.getSheetCenterX(), tol);
  EXPECT_NEAR(a.getSheetCenterY(), b.getSheetCenterY(), tol);
}
} // namespace

// ---------------------------------------------------------------- pattern (Eq. 1)

TEST(SquareWave, OutermostRingIsBlack)
{
  EXPECT_EQ(vpSSLPattern::squareWave(1.0, 0.5), 0);
  EXPECT_EQ(vpSSLPattern::squareWave(0.9, 0.5), 0);
  EXPECT_EQ(vpSSLPattern::squareWave(0.7072, 0.5), 0);
  EXPECT_EQ(vpSSLPattern::squareWave(0.7071, 0.5), 1);
  EXPECT_EQ(vpSSLPattern::circular(0.1, 0., 0.1, 0.5), 0);
  EXPECT_EQ(vpSSLPattern::circular(0., -0.1, 0.1, 0.5), 0);
}

TEST(SquareWave, RingBoundariesAtRadiusTimesSqrtPPowerK)
{
  // Ring k (0 = outermost, black) covers rho / R in (p^((k+1)/2), p^(k/2)]: a boundary belongs to
  // the ring inside it, and rings alternate with ratio sqrt(p) (1/sqrt(2) for p = 0.5).
  for (double p : {0.5, 0.3, 0.64}) {
    const double R = 0.1;
    for (int k = 0; k <= 40; ++k) {
      double rk = R * std::pow(std::sqrt(p), k);
      EXPECT_EQ(vpSSLPattern::circular(rk, 0., R, p), k % 2) << "p " << p << " boundary k " << k;
      EXPECT_EQ(vpSSLPattern::circular(0., rk * (1. - 1e-6), R, p), k % 2) << "p " << p << " inside k " << k;
      if (k > 0) {
        EXPECT_EQ(vpSSLPattern::circular(rk * (1. + 1e-6), 0., R, p), (k + 1) % 2) << "p " << p << " outside k " << k;
      }
    }
  }
}

TEST(SquareWave, SelfSimilarAndAntiSimilar)
{
  // p-similar: s(x) = s(p x); sqrt(p)-antisimilar: |s(x) - s(sqrt(p) x)| = 1 (paper Sec. 2.1).
  vpUniRand rng(42);
  for (double p : {0.5, 0.3, 0.8}) {
    for (int i = 0; i < 20000; ++i) {
      double x = rng.uniform(1e-6, 1.);
      int s = vpSSLPattern::squareWave(x, p);
      ASSERT_TRUE(s == 0 || s == 1);
      ASSERT_EQ(s, vpSSLPattern::squareWave(p * x, p)) << "p " << p << " x " << x;
      ASSERT_EQ(1 - s, vpSSLPattern::squareWave(std::sqrt(p) * x, p)) << "p " << p << " x " << x;
    }
  }
}

TEST(SquareWave, CircularIsRotationInvariant)
{
  vpUniRand rng(7);
  for (int i = 0; i < 2000; ++i) {
    double rho = rng.uniform(0.001, 0.1), a = rng.uniform(0., 2. * M_PI);
    EXPECT_EQ(vpSSLPattern::circular(rho * std::cos(a), rho * std::sin(a), 0.1, 0.5),
              vpSSLPattern::circular(rho, 0., 0.1, 0.5));
  }
}

TEST(SquareWave, OutsideAndCentreAndBadInput)
{
  EXPECT_EQ(vpSSLPattern::circular(0.0708, 0.0708, 0.1, 0.5), -1);
  EXPECT_EQ(vpSSLPattern::circular(0., 0., 0.1, 0.5), 1); // documented: the centre is white
  EXPECT_EQ(vpSSLPattern::squareWave(0., 0.5), 1);
  EXPECT_EQ(vpSSLPattern::linear(0., 0.2, 0.5), -1);
  EXPECT_EQ(vpSSLPattern::linear(0.2001, 0.2, 0.5), -1);
  EXPECT_EQ(vpSSLPattern::linear(0.2, 0.2, 0.5), 0);
  EXPECT_EQ(vpSSLPattern::linear(0.12, 0.2, 0.5), 1);
  EXPECT_EQ(vpSSLPattern::linear(0.05, 0.2, 0.5), 0);
  EXPECT_THROW(vpSSLPattern::squareWave(0.5, 1.0), vpException);
  EXPECT_THROW(vpSSLPattern::squareWave(0.5, 0.0), vpException);
  EXPECT_THROW(vpSSLPattern::squareWave(0.5, NAN), vpException);
  EXPECT_THROW(vpSSLPattern::circular(0., 0., 0., 0.5), vpException);
  EXPECT_THROW(vpSSLPattern::linear(0.1, -1., 0.5), vpException);
}

// ---------------------------------------------------------------- ssl3-a3 (doc/target-ssl3-a3.md)

TEST(Ssl3A3, MatchesSpecTable)
{
  vpSSLTarget t = vpSSLTarget::ssl3a3();
  EXPECT_EQ(t.getName(), "ssl3-a3");
  ASSERT_EQ(t.size(), 3u);
  const char *names[3] = {"B", "S1", "S2"};
  const double spec[3][4] = {{-0.103923, 0., 0., 0.100}, {0.051962, -0.090, 0., 0.050}, {0.051962, 0.090, 0., 0.050}};
  for (int i = 0; i < 3; ++i) {
    const vpSSLTargetLandmark &lm = t.getLandmark(i);
    EXPECT_EQ(lm.name, names[i]);
    EXPECT_NEAR(lm.x, spec[i][0], kSpecTol);
    EXPECT_NEAR(lm.y, spec[i][1], kSpecTol);
    EXPECT_NEAR(lm.z, spec[i][2], kSpecTol);
    EXPECT_NEAR(lm.radius, spec[i][3], kSpecTol);
    EXPECT_EQ(t.findLandmark(names[i]), i);
  }
  EXPECT_DOUBLE_EQ(t.getP(), 0.5);
  EXPECT_NEAR(t.getSheetWidth(), 0.420, kSpecTol);
  EXPECT_NEAR(t.getSheetHeight(), 0.297, kSpecTol);
  EXPECT_NEAR(t.getSheetCenterX(), -0.051, kSpecTol);
  EXPECT_NEAR(t.getSheetCenterY(), 0.0, kSpecTol);
  EXPECT_DOUBLE_EQ(t.getMaxRadius(), 0.100);
  EXPECT_DOUBLE_EQ(t.getMinRadius(), 0.050);
  EXPECT_EQ(t.findLandmark("S3"), -1);
}

TEST(Ssl3A3, EquilateralTriangleOfSide180mmCentredOnOrigin)
{
  std::vector<vpPoint> P = vpSSLTarget::ssl3a3().getPoints();
  ASSERT_EQ(P.size(), 3u);
  double cx = 0., cy = 0.;
  for (int i = 0; i < 3; ++i) {
    const vpPoint &a = P[i], &b = P[(i + 1) % 3];
    EXPECT_NEAR(std::hypot(a.get_oX() - b.get_oX(), a.get_oY() - b.get_oY()), 0.180, kSpecTol) << i;
    EXPECT_DOUBLE_EQ(a.get_oZ(), 0.);
    cx += a.get_oX() / 3.;
    cy += a.get_oY() / 3.;
  }
  EXPECT_NEAR(cx, 0., kSpecTol);
  EXPECT_NEAR(cy, 0., kSpecTol);
}

TEST(Ssl3A3, BS1S2RunClockwiseSeenFromPrintedSide)
{
  // Seen from the printed side with X right and Y down (image convention), a positive z component of
  // (S1 - B) x (S2 - B) means clockwise on screen: B on the left, S1 top right, S2 bottom right.
  vpSSLTarget t = vpSSLTarget::ssl3a3();
  const vpSSLTargetLandmark &b = t.getLandmark(0), &s1 = t.getLandmark(1), &s2 = t.getLandmark(2);
  double cross = (s1.x - b.x) * (s2.y - b.y) - (s1.y - b.y) * (s2.x - b.x);
  EXPECT_GT(cross, 0.01);
  EXPECT_LT(s1.y, 0.); // S1 above the X axis on the printed sheet
  EXPECT_LT(b.x, s1.x);
}

TEST(Ssl3A3, DiscsFitOnTheA3SheetWithoutOverlap)
{
  vpSSLTarget t = vpSSLTarget::ssl3a3();
  for (const vpSSLTargetLandmark &lm : t.getLandmarks()) {
    EXPECT_LE(std::fabs(lm.x - t.getSheetCenterX()) + lm.radius, 0.5 * t.getSheetWidth()) << lm.name;
    EXPECT_LE(std::fabs(lm.y - t.getSheetCenterY()) + lm.radius, 0.5 * t.getSheetHeight()) << lm.name;
  }
  const std::vector<vpSSLTargetLandmark> &L = t.getLandmarks();
  for (size_t i = 0; i < L.size(); ++i) {
    for (size_t j = i + 1; j < L.size(); ++j) {
      EXPECT_GT(std::hypot(L[i].x - L[j].x, L[i].y - L[j].y), L[i].radius + L[j].radius);
    }
  }
}

TEST(Ssl3A3, DataFileEqualsBuiltIn)
{
  vpSSLTarget file = vpSSLTarget::load(dataFile("ssl3-a3.txt"));
  expectSameTarget(file, vpSSLTarget::ssl3a3(), 1e-12);
  expectSameTarget(vpSSLTarget::fromName(dataFile("ssl3-a3.txt")), vpSSLTarget::ssl3a3(), 1e-12);
  expectSameTarget(vpSSLTarget::fromName("ssl3-a3"), vpSSLTarget::ssl3a3(), 0.);
}

TEST(Ssl1Single, OneLandmarkOf100mmOnA4)
{
  vpSSLTarget t = vpSSLTarget::load(dataFile("ssl1-single.txt"));
  EXPECT_EQ(t.getName(), "ssl1-single");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t.getLandmark(0).radius, 0.1);
  EXPECT_DOUBLE_EQ(t.getLandmark(0).p, 0.5);
  EXPECT_DOUBLE_EQ(t.getSheetWidth(), 0.210);
  EXPECT_DOUBLE_EQ(t.getSheetHeight(), 0.297);
}

// ---------------------------------------------------------------- target files

TEST_F(TargetFileTest, SaveLoadRoundTripIsIdentical)
{
  vpSSLTarget t;
  t.setName("odd-numbers");
  vpSSLTargetLandmark a, b;
  a.name = "A";
  a.x = 1. / 3.;
  a.y = -2. / 7.;
  a.z = 1e-3 / 3.;
  a.radius = 0.1 / 3.;
  a.p = 0.6;
  b.name = "Bee";
  b.p = 0.6;
  b.x = -0.123456789012345;
  b.y = 0.3;
  b.radius = 0.05;
  t.addLandmark(a);
  t.addLandmark(b);
  t.setSheet(1.1, 0.9, 0.01 / 3., -0.02);
  for (const vpSSLTarget &src : {t, vpSSLTarget::ssl3a3()}) {
    std::string path = (m_dir / "saved.txt").string();
    src.save(path);
    expectSameTarget(vpSSLTarget::load(path), src, 0.);
  }
}

TEST_F(TargetFileTest, OmittedPIsHalfAndOmittedSheetIsBoundingBoxPlusLargestRadius)
{
  vpSSLTarget t = vpSSLTarget::load(write("name t\nlandmark A 0 0 0 0.1\nlandmark B 0.3 0.1 0 0.05 0.5\n"));
  EXPECT_DOUBLE_EQ(t.getLandmark(0).p, 0.5);
  EXPECT_DOUBLE_EQ(t.getLandmark(1).p, 0.5);
  EXPECT_DOUBLE_EQ(t.getP(), 0.5);
  // Landmarks of one target share p (the detector matches one square wave): a different one is an error.
  EXPECT_THROW(vpSSLTarget::load(write("name t\nlandmark A 0 0 0 0.1\nlandmark B 0.3 0.1 0 0.05 0.4\n")), vpException);
  // Discs span x in [-0.1, 0.35], y in [-0.1, 0.15]; margin 0.1 on each side.
  EXPECT_NEAR(t.getSheetWidth(), 0.65, 1e-12);
  EXPECT_NEAR(t.getSheetHeight(), 0.45, 1e-12);
  EXPECT_NEAR(t.getSheetCenterX(), 0.125, 1e-12);
  EXPECT_NEAR(t.getSheetCenterY(), 0.025, 1e-12);
}

TEST_F(TargetFileTest, CommentsBlankLinesCrlfAndPlusSignsAreAccepted)
{
  vpSSLTarget t = vpSSLTarget::load(write("\r\n# c\n  name   t  # trailing\r\n\n"
                                          "landmark A +0.1 -0.0 0 0.05 # p omitted\r\n"));
  EXPECT_EQ(t.getName(), "t");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t.getLandmark(0).x, 0.1);
}

TEST_F(TargetFileTest, NonexistentFileCannotOpen)
{
  std::string path = (m_dir / "nope.txt").string();
  try {
    vpSSLTarget::load(path);
    FAIL() << "no exception";
  } catch (const vpException &e) {
    EXPECT_EQ(e.getCode(), vpException::ioError);
    EXPECT_EQ(e.getStringMessage(), path + ": cannot open");
  }
  EXPECT_THROW(vpSSLTarget::fromName("ssl9-nothing"), vpException);
  EXPECT_THROW(vpSSLTarget::load(m_dir.string()), vpException); // a directory
}

TEST_F(TargetFileTest, RadiusNotANumber)
{
  std::string m = loadError(kHeader + "landmark B -0.1 0 0 abc\n");
  EXPECT_NE(m.find("t.txt:4: radius: not a number: \"abc\""), std::string::npos) << m;
}

TEST_F(TargetFileTest, NumberWithTrailingGarbageOrInfinite)
{
  std::string m = loadError(kHeader + "landmark B 0.1m 0 0 0.1\n");
  EXPECT_NE(m.find("t.txt:4: x: not a number: \"0.1m\""), std::string::npos) << m;
  m = loadError(kHeader + "landmark B 0 inf 0 0.1\n");
  EXPECT_NE(m.find("t.txt:4: y: not a finite number"), std::string::npos) << m;
}

TEST_F(TargetFileTest, RadiusMustBePositive)
{
  std::string m = loadError(kHeader + "landmark B -0.1 0 0 0\n");
  EXPECT_NE(m.find("t.txt:4: radius: must be > 0"), std::string::npos) << m;
  m = loadError(kHeader + "landmark B -0.1 0 0 -0.1\n");
  EXPECT_NE(m.find("t.txt:4: radius: must be > 0"), std::string::npos) << m;
}

TEST_F(TargetFileTest, UnknownKeyword)
{
  std::string m = loadError("name t\nlanmark B 0 0 0 0.1\n");
  EXPECT_NE(m.find("t.txt:2: unknown keyword \"lanmark\""), std::string::npos) << m;
}

TEST_F(TargetFileTest, WrongFieldCount)
{
  std::string m = loadError(kHeader + "landmark B 0 0 0 0.1\nlandmark S1 0 0\n");
  EXPECT_NE(m.find("t.txt:5: landmark: expected 6 or 7 fields, got 4"), std::string::npos) << m;
  m = loadError("name t\nsheet 0.4 0.3 0\n");
  EXPECT_NE(m.find("t.txt:2: sheet: expected 5 fields, got 4"), std::string::npos) << m;
  m = loadError("name two words\n");
  EXPECT_NE(m.find("t.txt:1: name: expected 2 fields, got 3"), std::string::npos) << m;
}

TEST_F(TargetFileTest, DuplicateLandmarkName)
{
  std::string m = loadError(kHeader + "landmark B -0.1 0 0 0.05\nlandmark B 0.1 0 0 0.05\n");
  EXPECT_NE(m.find("t.txt:5: name: duplicate landmark name \"B\" (line 4)"), std::string::npos) << m;
}

TEST_F(TargetFileTest, POutsideItsRange)
{
  for (const char *p : {"1", "0", "1.5", "-0.5", "0.1", "0.99999999"}) {
    std::string m = loadError(kHeader + "landmark B 0 0 0 0.1 " + p + "\n");
    EXPECT_NE(m.find("t.txt:4: p: must be in [0.2, 0.8]"), std::string::npos) << m;
  }
}

TEST_F(TargetFileTest, OverlappingLandmarks)
{
  std::string m = loadError(kHeader + "landmark B 0 0 0 0.1\nlandmark S1 0.1 0 0 0.05\n");
  EXPECT_NE(m.find("t.txt:5: landmark: \"S1\" overlaps \"B\""), std::string::npos) << m;
  // Touching discs are allowed.
  EXPECT_NO_THROW(vpSSLTarget::load(write(kHeader + "landmark B 0 0 0 0.1\nlandmark S1 -0.15 0 0 0.05\n")));
}

TEST_F(TargetFileTest, LandmarkOffTheSheet)
{
  std::string m = loadError("name t\nlandmark B 0.12 0 0 0.05\nsheet 0.3 0.2 0 0\n");
  EXPECT_NE(m.find("t.txt:2: landmark: \"B\" does not fit on the sheet"), std::string::npos) << m;
}

TEST_F(TargetFileTest, MissingNameOrLandmarks)
{
  std::string m = loadError("sheet 0.3 0.2 0 0\nlandmark B 0 0 0 0.05\n");
  EXPECT_NE(m.find("t.txt: name: missing"), std::string::npos) << m;
  m = loadError("# only a comment\nname t\n");
  EXPECT_NE(m.find("t.txt: landmark: none"), std::string::npos) << m;
  m = loadError("");
  EXPECT_NE(m.find("t.txt: name: missing"), std::string::npos) << m;
}

TEST_F(TargetFileTest, NameOrSheetGivenTwice)
{
  std::string m = loadError("name t\nname u\n");
  EXPECT_NE(m.find("t.txt:2: name: given twice (first on line 1)"), std::string::npos) << m;
  m = loadError("name t\nsheet 0.3 0.2 0 0\nsheet 0.3 0.2 0 0\n");
  EXPECT_NE(m.find("t.txt:3: sheet: given twice (first on line 2)"), std::string::npos) << m;
}

TEST_F(TargetFileTest, SheetSizeMustBePositive)
{
  std::string m = loadError("name t\nsheet 0 0.2 0 0\n");
  EXPECT_NE(m.find("t.txt:2: width: must be > 0"), std::string::npos) << m;
  m = loadError("name t\nsheet 0.3 -1 0 0\n");
  EXPECT_NE(m.find("t.txt:2: height: must be > 0"), std::string::npos) << m;
  m = loadError("name t\nsheet 0.3 0.2 x 0\n");
  EXPECT_NE(m.find("t.txt:2: center_x: not a number: \"x\""), std::string::npos) << m;
}

TEST(TargetModel, AddLandmarkRejectsBadLandmarks)
{
  vpSSLTarget t;
  vpSSLTargetLandmark a;
  a.name = "A";
  a.radius = 0.1;
  t.addLandmark(a);
  vpSSLTargetLandmark bad = a;
  EXPECT_THROW(t.addLandmark(bad), vpException); // duplicate name
  bad.name = "B";
  EXPECT_THROW(t.addLandmark(bad), vpException); // overlaps A
  bad.x = 1.;
  bad.radius = 0.;
  EXPECT_THROW(t.addLandmark(bad), vpException);
  bad.radius = 0.1;
  bad.p = 1.;
  EXPECT_THROW(t.addLandmark(bad), vpException);
  bad.p = 0.5;
  bad.name = "two words";
  EXPECT_THROW(t.addLandmark(bad), vpException);
  EXPECT_EQ(t.size(), 1u);
  EXPECT_THROW(t.getLandmark(1), vpException);
  EXPECT_THROW(t.setSheet(0., 1., 0., 0.), vpException);
  EXPECT_THROW(vpSSLTarget().getMaxRadius(), vpException);
  EXPECT_THROW(vpSSLTarget().save("/nonexistent-dir/x.txt"), vpException); // no name, no landmark
}

TEST_F(TargetFileTest, AutomaticSheetBeyondTheLimitsIsRejectedSoThatSavedTargetsLoadBack)
{
  // Landmarks 120 m apart: their automatic sheet is larger than a written sheet may be (100 m); accepting it would
  // write a file that load() rejects.
  const std::string e = loadError("name t\nlandmark B -60 0 0 0.1 0.5\nlandmark S1 60 0 0 0.05 0.5\n");
  EXPECT_NE(e.find(": sheet: the automatic sheet around the landmarks: width: must be at most"), std::string::npos)
      << e;
}
