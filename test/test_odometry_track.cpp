// vpSSLOdometryTrack: the odometry CSV of doc/recordings.md read in both rotation forms, errors naming the file, the
// line and the column, interpolation that reproduces a uniform motion and never extrapolates, and the frames a
// recording writes (time from the first image, positions from the first sample).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include <visp3/core/vpException.h>
#include <visp3/core/vpQuaternionVector.h>
#include <visp3/core/vpThetaUVector.h>
#include <visp3/ssl_io/vpSSLOdometryTrack.h>

namespace {
std::string writeCsv(const std::string &name, const std::string &text)
{
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("visp_ssl_test_odometry_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path) << text;
  return path.string();
}

std::string loadError(const std::string &name, const std::string &text)
{
  const std::string path = writeCsv(name, text);
  try {
    vpSSLOdometryTrack::load(path);
  } catch (const vpException &e) {
    std::filesystem::remove(path);
    return e.getStringMessage().substr(path.size());
  }
  std::filesystem::remove(path);
  return "no error";
}
} // namespace

TEST(OdometryTrack, ThetaUAndQuaternionRowsGiveTheSamePoses)
{
  const vpThetaUVector tu(0.1, -0.2, 0.3);
  const vpQuaternionVector q{vpRotationMatrix(tu)};
  char quaternion[256];
  std::snprintf(quaternion, sizeof(quaternion), "t,tx,ty,tz,qx,qy,qz,qw,note\n5,1,2,3,%.17g,%.17g,%.17g,%.17g,a\n",
                q.x(), q.y(), q.z(), q.w());
  const std::string a = writeCsv("tu.csv", "t,tx,ty,tz,tux,tuy,tuz\r\n5,1,2,3,0.1,-0.2,0.3\r\n");
  const std::string b = writeCsv("q.csv", quaternion);
  const vpSSLOdometryTrack ta = vpSSLOdometryTrack::load(a), tb = vpSSLOdometryTrack::load(b);
  std::filesystem::remove(a);
  std::filesystem::remove(b);
  ASSERT_EQ(ta.size(), 1u);
  ASSERT_EQ(tb.size(), 1u);
  const vpHomogeneousMatrix Ma = ta.interpolate(5.), Mb = tb.interpolate(5.);
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 4; ++c)
      EXPECT_NEAR(Ma[r][c], Mb[r][c], 1e-12);
  EXPECT_EQ(Ma.getTranslationVector(), vpTranslationVector(1., 2., 3.));
}

TEST(OdometryTrack, BadFilesAreNamedByLineAndColumn)
{
  EXPECT_EQ(loadError("h.csv", "time,x,y,z\n0,0,0,0\n"),
            ":1: header: expected t,tx,ty,tz,tux,tuy,tuz or t,tx,ty,tz,qx,qy,qz,qw, got \"time,x,y,z\"");
  EXPECT_EQ(loadError("o.csv", "t,tx,ty,tz,tux,tuy,tuz\n1,0,0,0,0,0,0\n2,0,0,0,0,0,0\n1.5,0,0,0,0,0,0\n"),
            ":4: t: not increasing (1.5 after 2.000000)");
  EXPECT_EQ(loadError("n.csv", "t,tx,ty,tz,tux,tuy,tuz\n1,0,abc,0,0,0,0\n"), ":2: ty: not a number: \"abc\"");
  EXPECT_EQ(loadError("q.csv", "t,tx,ty,tz,qx,qy,qz,qw\n1,0,0,0,0,0,0,0.9\n"),
            ":2: qw: the quaternion's norm is 0.900000, not 1 within 1e-3");
  EXPECT_EQ(loadError("c.csv", "t,tx,ty,tz,tux,tuy,tuz\n1,0,0,0,0,0\n"), ":2: row: expected 7 cells, got 6");
  EXPECT_EQ(loadError("e.csv", "t,tx,ty,tz,tux,tuy,tuz\n"), ":0: file: no odometry row after the header");
  EXPECT_EQ(loadError("g.csv", "t,tx,ty,tz,tux,tuy,tuz\n1,0,0,0,0,0,0\n\n2,0,0,0,0,0,0\n"),
            ":4: row: a row after an empty line (a hole in the table)");
}

TEST(OdometryTrack, SamplesAreReadBackAsLoadedAndBoundsAreThoseOfTheReader)
{
  const std::string path = writeCsv("s.csv", "t,tx,ty,tz,tux,tuy,tuz\n1,2,3,4,0,0,0.5\n7.5,-1,0,0,0,0,0\n");
  const vpSSLOdometryTrack track = vpSSLOdometryTrack::load(path);
  std::filesystem::remove(path);
  ASSERT_EQ(track.size(), 2u);
  EXPECT_EQ(track.getTime(0), 1.);
  EXPECT_EQ(track.getTime(1), 7.5);
  EXPECT_EQ(track.getPose(0).getTranslationVector(), vpTranslationVector(2., 3., 4.));
  EXPECT_NEAR(vpThetaUVector(track.getPose(0).getRotationMatrix())[2], 0.5, 1e-12);
  EXPECT_EQ(track.getPose(1).getTranslationVector(), vpTranslationVector(-1., 0., 0.));
  EXPECT_THROW(track.getTime(2), vpException);
  EXPECT_THROW(track.getPose(2), vpException);
  // The public bounds are the ones load() applies: a cell just beyond each is refused, one at it accepted.
  EXPECT_EQ(loadError("bt.csv", "t,tx,ty,tz,tux,tuy,tuz\n1e10,1e7,0,0,10,0,0\n"), "no error");
  EXPECT_EQ(loadError("t.csv", "t,tx,ty,tz,tux,tuy,tuz\n1.0001e10,0,0,0,0,0,0\n"),
            ":2: t: 1.0001e10 is beyond +-1e+10 s");
  EXPECT_EQ(loadError("x.csv", "t,tx,ty,tz,tux,tuy,tuz\n1,0,-1.0001e7,0,0,0,0\n"),
            ":2: ty: -1.0001e7 is beyond +-1e+07 m");
  EXPECT_EQ(loadError("r.csv", "t,tx,ty,tz,tux,tuy,tuz\n1,0,0,0,0,10.001,0\n"), ":2: tuy: 10.001 is beyond +-10 rad");
  EXPECT_EQ(vpSSLOdometryTrack::maxTime(), 1e10);
  EXPECT_EQ(vpSSLOdometryTrack::maxTranslation(), 1e7);
  EXPECT_EQ(vpSSLOdometryTrack::maxRotation(), 10.);
}

TEST(OdometryTrack, InterpolationFollowsAUniformMotionAndNeverExtrapolates)
{
  // 1 m/s along x while turning at 1 rad/s about z, sampled every 0.5 s.
  vpSSLOdometryTrack track;
  for (int k = 0; k <= 4; ++k) {
    const double t = 10. + 0.5 * k;
    track.add(t, vpHomogeneousMatrix(t - 10., 0., 0., 0., 0., t - 10.));
  }
  const vpHomogeneousMatrix M = track.interpolate(11.2);
  const vpHomogeneousMatrix expected(1.2, 0., 0., 0., 0., 1.2);
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 4; ++c)
      EXPECT_NEAR(M[r][c], expected[r][c], 1e-12);
  EXPECT_TRUE(track.covers(10.) && track.covers(12.));
  EXPECT_FALSE(track.covers(9.999) || track.covers(12.001));
  EXPECT_THROW(track.interpolate(12.001), vpException);
  EXPECT_THROW(track.add(12., vpHomogeneousMatrix()), vpException) << "a time that does not increase";
}

TEST(OdometryTrack, RecordingFramesCountFromTheFirstImageAndTheFirstPosition)
{
  vpSSLOdometryTrack track;
  track.add(1.7e9, vpHomogeneousMatrix(500000., 6000000., 10., 0., 0., 0.5));
  track.add(1.7e9 + 2., vpHomogeneousMatrix(500002., 6000000., 10., 0., 0., 0.5));
  vpSSLSequenceFrame frame;
  track.stampFrame(1.7e9 + 1.25, 1.7e9 + 0.25, frame);
  EXPECT_DOUBLE_EQ(frame.t, 1.);
  EXPECT_EQ(frame.extras[vpSSLOdometryTrack::stampColumn()], "1700000001.250000");
  ASSERT_TRUE(frame.hasOdometry);
  EXPECT_NEAR(frame.oMv[0], 1.25, 1e-6);
  EXPECT_NEAR(frame.oMv[1], 0., 1e-6);
  EXPECT_NEAR(frame.oMv[2], 0., 1e-6);
  EXPECT_NEAR(frame.oMv[5], 0.5, 1e-12) << "axes kept";

  vpSSLSequenceFrame without;
  vpSSLOdometryTrack().stampFrame(3., 1., without);
  EXPECT_FALSE(without.hasOdometry);
  EXPECT_DOUBLE_EQ(without.t, 2.);
}
