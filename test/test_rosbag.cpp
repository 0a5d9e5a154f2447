// vpSSLRosbagReader on bags the test writes itself with rosbag_storage (ssl_test_bag.h): topics, intrinsics,
// images and odometry read back as written, errors naming the bag and the topic, and the tracker fed directly.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include <unistd.h>

#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_rosbag/vpSSLRosbagReader.h>

#include "ssl_test_bag.h"

namespace {
// A scratch directory per test, removed after it.
class Rosbag : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const ::testing::TestInfo *info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = std::filesystem::temp_directory_path() /
            ("visp_ssl_test_rosbag_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(m_dir);
  }
  void TearDown() override
  {
    std::error_code ec;
    std::filesystem::remove_all(m_dir, ec);
  }
  std::string scratch(const std::string &name) const { return (m_dir / name).string(); }
  void expectReadsBack(bool compressed) const;

  std::filesystem::path m_dir;
};

// The project's pose of a REP 103 one: world North-East-Down from East-North-Up, body forward-starboard-down from
// forward-left-up, written out axis by axis rather than with the reader's matrices.
vpHomogeneousMatrix toNedFrd(const vpHomogeneousMatrix &enu)
{
  vpHomogeneousMatrix ned;
  for (unsigned int r = 0; r < 3; ++r) {
    const unsigned int rr = r == 0 ? 1 : (r == 1 ? 0 : 2); // N = y_enu, E = x_enu, D = -z_enu
    const double s = r == 2 ? -1. : 1.;
    ned[r][3] = s * enu[rr][3];
    ned[r][0] = s * enu[rr][0];  // forward stays forward
    ned[r][1] = -s * enu[rr][1]; // starboard = -left
    ned[r][2] = -s * enu[rr][2]; // down = -up
  }
  return ned;
}

void expectNear(const vpHomogeneousMatrix &a, const vpHomogeneousMatrix &b, double tolerance)
{
  for (unsigned int r = 0; r < 3; ++r)
    for (unsigned int c = 0; c < 4; ++c)
      EXPECT_NEAR(a[r][c], b[r][c], tolerance) << "element " << r << "," << c;
}

} // namespace

void Rosbag::expectReadsBack(bool compressed) const
{
  ssltest::TestBagOptions options;
  options.compressed = compressed;
  const std::string bag = scratch("dive.bag");
  const ssltest::TestBag written = ssltest::writeTestBag(bag, options);

  vpSSLRosbagReader reader;
  reader.open(bag);
  const std::vector<vpSSLRosbagTopic> &topics = reader.getTopics();
  ASSERT_EQ(topics.size(), 3u);
  EXPECT_EQ(topics[0].name, "/camera/camera_info");
  EXPECT_EQ(topics[0].type, "sensor_msgs/CameraInfo");
  EXPECT_EQ(topics[0].count, 4u);
  EXPECT_EQ(topics[1].name, "/camera/image_raw");
  EXPECT_EQ(topics[1].type, compressed ? "sensor_msgs/CompressedImage" : "sensor_msgs/Image");
  EXPECT_EQ(topics[2].name, "/odom");
  EXPECT_EQ(topics[2].type, "nav_msgs/Odometry");
  EXPECT_EQ(topics[2].count, written.odometryTimes.size());

  reader.selectTopics("/camera/image_raw", "/camera/camera_info", "/odom");
  const vpCameraParameters &cam = reader.getCameraParameters();
  EXPECT_EQ(cam.get_px(), written.cam.get_px());
  EXPECT_EQ(cam.get_py(), written.cam.get_py());
  EXPECT_EQ(cam.get_u0(), written.cam.get_u0());
  EXPECT_EQ(cam.get_v0(), written.cam.get_v0());
  EXPECT_EQ(reader.getImageWidth(), written.width);
  EXPECT_EQ(reader.getImageHeight(), written.height);
  EXPECT_EQ(reader.getImageCount(), 4u);
  ASSERT_EQ(reader.getOdometry().size(), written.odometryTimes.size());

  vpSSLSequenceFrame frame;
  vpImage<unsigned char> I;
  unsigned int n = 0;
  while (reader.acquire(frame, I)) {
    ASSERT_LT(n, written.images.size());
    EXPECT_EQ(frame.index, n);
    EXPECT_EQ(frame.t, written.imageTimes[n] - written.imageTimes[0]);
    char stamp[32];
    std::snprintf(stamp, sizeof(stamp), "%.6f", written.imageTimes[n]);
    EXPECT_EQ(frame.extras["stamp"], stamp);
    EXPECT_TRUE(I == written.images[n]) << "image " << n << " differs from the one written";
    // Each image falls halfway between two odometry samples of a motion whose position and heading are linear in
    // time: the interpolated pose is the motion's own pose at the image time.
    ASSERT_TRUE(frame.hasOdometry);
    // The origin is moved to the first sample's position (0, 0, -1 in East-North-Up).
    const double dt = written.imageTimes[n] - written.odometryTimes[0], yaw = 0.2 * dt;
    const vpHomogeneousMatrix enu(vpTranslationVector(0.5 * dt, 0., 0.), vpRotationMatrix(vpRxyzVector(0., 0., yaw)));
    expectNear(vpHomogeneousMatrix(frame.oMv), toNedFrd(enu), 1e-9);
    ++n;
  }
  EXPECT_EQ(n, 4u);
  EXPECT_FALSE(reader.acquire(frame, I)) << "the end stays the end";
}

TEST_F(Rosbag, ImagesIntrinsicsAndOdometryReadBackAsWritten)
{
  expectReadsBack(false);
}

TEST_F(Rosbag, CompressedImagesReadBackBitForBit)
{
  expectReadsBack(true);
}

TEST_F(Rosbag, Rep103OdometryBecomesNorthEastDownAndForwardStarboardDown)
{
  // A vehicle 1 m East, 2 m North, 0.5 m up, facing East: 2 m North, 1 m East, 0.5 m above the origin (z = -0.5),
  // its starboard pointing South and its keel down.
  const vpHomogeneousMatrix enu(vpTranslationVector(1., 2., 0.5), vpRotationMatrix());
  const vpRotationMatrix R({0, -1, 0, 1, 0, 0, 0, 0, 1});
  expectNear(toNedFrd(enu), vpHomogeneousMatrix(vpTranslationVector(2., 1., -0.5), R), 0.);
}

TEST_F(Rosbag, AsIsOdometryIsKept)
{
  const std::string bag = scratch("as-is.bag");
  const ssltest::TestBag written = ssltest::writeTestBag(bag);
  vpSSLRosbagReader reader;
  reader.setOdometryConvention(vpSSLRosbagReader::ODOMETRY_AS_IS);
  reader.open(bag);
  reader.selectTopics("/camera/image_raw", "/camera/camera_info", "/odom");
  ASSERT_TRUE(reader.getOdometry().covers(written.odometryTimes[2]));
  expectNear(reader.getOdometry().interpolate(written.odometryTimes[2]), written.odometryPoses[2], 1e-12);
}

TEST_F(Rosbag, MissingTopicNamesTheBagAndTheTopicsOfThatType)
{
  const std::string bag = scratch("dive.bag");
  ssltest::writeTestBag(bag);
  vpSSLRosbagReader reader;
  reader.open(bag);
  try {
    reader.selectTopics("/camera/image_rect", "/camera/camera_info");
    FAIL() << "no exception";
  } catch (const vpException &e) {
    EXPECT_EQ(e.getStringMessage(), bag + ": /camera/image_rect: no such topic in the bag (sensor_msgs/Image or "
                                          "sensor_msgs/CompressedImage topics: /camera/image_raw)");
  }
  try {
    reader.selectTopics("/camera/image_raw", "/odom");
    FAIL() << "no exception";
  } catch (const vpException &e) {
    EXPECT_EQ(e.getStringMessage(), bag + ": /odom: has type nav_msgs/Odometry, expected sensor_msgs/CameraInfo");
  }
}

TEST_F(Rosbag, OdometryEndingBeforeTheImagesIsRefusedAtTheFirstUncoveredImage)
{
  ssltest::TestBagOptions options;
  options.odometryEnd = 0.15; // covers images 0 and 1 (at +0 and +0.1 s), not image 2 (+0.2 s)
  const std::string bag = scratch("short-odometry.bag");
  ssltest::writeTestBag(bag, options);
  vpSSLRosbagReader reader;
  reader.open(bag);
  reader.selectTopics("/camera/image_raw", "/camera/camera_info", "/odom");
  vpSSLSequenceFrame frame;
  vpImage<unsigned char> I;
  EXPECT_TRUE(reader.acquire(frame, I));
  EXPECT_TRUE(reader.acquire(frame, I));
  try {
    reader.acquire(frame, I);
    FAIL() << "no exception";
  } catch (const vpException &e) {
    EXPECT_NE(e.getStringMessage().find(bag + ": /camera/image_raw: image 2: odometry: time 1000.22"),
              std::string::npos)
        << e.getStringMessage();
    EXPECT_NE(e.getStringMessage().find("outside"), std::string::npos) << e.getStringMessage();
  }
}

TEST_F(Rosbag, NotABagIsOneIoError)
{
  const std::string path = scratch("not-a.bag");
  std::ofstream(path) << "#ROSBAG V1.2\nnot a bag\n";
  vpSSLRosbagReader reader;
  try {
    reader.open(path);
    FAIL() << "no exception";
  } catch (const vpException &e) {
    EXPECT_EQ(e.getCode(), vpException::ioError);
    EXPECT_EQ(e.getStringMessage().rfind(path + ": cannot read the bag: ", 0), 0u) << e.getStringMessage();
  }
  EXPECT_THROW(reader.open(scratch("missing.bag")), vpException);
}

TEST_F(Rosbag, CorruptLengthsAreRefusedBeforeRosbagStorageReadsThem)
{
  // rosbag_storage allocates a record's declared header length before reading it, and parses a chunk's records at
  // the index's offsets: the reader names the byte instead.
  const std::string good = scratch("good.bag");
  ssltest::TestBagOptions options;
  options.frames = 1;
  options.width = 32;
  options.height = 24;
  ssltest::writeTestBag(good, options);
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  auto openError = [this](const std::string &name, const std::string &content) {
    const std::string path = scratch(name);
    std::ofstream(path, std::ios::binary) << content;
    vpSSLRosbagReader reader;
    try {
      reader.open(path);
    } catch (const vpException &e) {
      EXPECT_EQ(e.getCode(), vpException::ioError);
      return e.getStringMessage().substr(path.size());
    }
    return std::string("no error");
  };
  EXPECT_EQ(openError("good-copy.bag", bytes), "no error");
  std::string huge = bytes;
  huge.replace(13, 4, std::string("\xf0\xff\xff\xff", 4));
  EXPECT_EQ(openError("huge.bag", huge),
            ": cannot read the bag: byte 13: record header of 4294967280 bytes beyond the end of its file");
  EXPECT_EQ(openError("cut.bag", bytes.substr(0, bytes.size() - 7)).rfind(": cannot read the bag: byte ", 0), 0u);
}

TEST_F(Rosbag, BadImageMessagesAreRefusedBeforeTheirDecoders)
{
  // A mono8 Image whose data is shorter than step x height (cv_bridge would read past it), a CompressedImage
  // whose PNG declares 20000 x 20000 pixels (OpenCV would allocate them) and one cut short (libpng would print
  // on stderr): each a badValue naming the image.
  ros::Time::init();
  const std::string path = scratch("bad-images.bag");
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    sensor_msgs::CameraInfo info;
    info.K = {600., 0., 16., 0., 600., 12., 0., 0., 1.};
    bag.write("/info", ros::Time(1.), info);
    sensor_msgs::Image raw;
    raw.header.stamp = ros::Time(1.);
    raw.width = 32;
    raw.height = 24;
    raw.encoding = "mono8";
    raw.step = 32;
    raw.data.assign(32 * 23, 0);
    bag.write("/raw", ros::Time(1.), raw);
    sensor_msgs::CompressedImage png;
    png.header.stamp = ros::Time(1.);
    png.format = "mono8; png compressed";
    cv::imencode(".png", cv::Mat(24, 32, CV_8UC1, cv::Scalar(100)), png.data);
    sensor_msgs::CompressedImage huge = png;
    const unsigned char size[8] = {0, 0, 0x4E, 0x20, 0, 0, 0x4E, 0x20};
    std::copy(size, size + 8, huge.data.begin() + 16);
    bag.write("/huge", ros::Time(1.), huge);
    sensor_msgs::CompressedImage cut = png;
    cut.data.resize(cut.data.size() - 20);
    bag.write("/cut", ros::Time(1.), cut);
  }
  auto acquireError = [&](const std::string &topic) {
    vpSSLRosbagReader reader;
    reader.open(path);
    reader.selectTopics(topic, "/info");
    vpSSLSequenceFrame frame;
    vpImage<unsigned char> I;
    try {
      reader.acquire(frame, I);
    } catch (const vpException &e) {
      EXPECT_EQ(e.getCode(), vpException::badValue) << e.getStringMessage();
      return e.getStringMessage().substr(path.size());
    }
    return std::string("no error");
  };
  EXPECT_EQ(acquireError("/raw"), ": /raw: image 0: data of 736 bytes, 24 rows of 32 expected");
  EXPECT_EQ(acquireError("/huge"), ": /huge: image 0: compressed image: PNG header: 20000 x 20000 pixels: a side "
                                   "exceeds the limit of 16384 pixels");
  EXPECT_EQ(acquireError("/cut").rfind(": /cut: image 0: compressed image: PNG data truncated", 0), 0u);
}

TEST_F(Rosbag, FramesFeedTheTrackerDirectly)
{
  const std::string bag = scratch("dive.bag");
  const ssltest::TestBag written = ssltest::writeTestBag(bag);
  vpSSLRosbagReader reader;
  reader.open(bag);
  reader.selectTopics("/camera/image_raw", "/camera/camera_info", "/odom");
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), reader.getCameraParameters());
  vpSSLSequenceFrame frame;
  vpImage<unsigned char> I;
  while (reader.acquire(frame, I)) {
    tracker.track(I);
  }
  ASSERT_TRUE(tracker.hasPose());
  const vpTranslationVector error =
      tracker.getPose().getTranslationVector() - written.cMo.back().getTranslationVector();
  EXPECT_LT(error.frobeniusNorm(), 0.05) << "estimate " << tracker.getPose().getTranslationVector().t();
}
