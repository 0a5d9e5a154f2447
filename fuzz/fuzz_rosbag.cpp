// libFuzzer target: the ROS 1 bag reader (vpSSLRosbagReader over rosbag_storage) on any bytes written as a .bag
// file. The reader picks the first topic of each type it lists (so that mutated topic names and types are
// followed), reads the intrinsics and odometry, and acquires up to 4 images. Anything it accepts is within
// doc/input-limits.md: intrinsics as vpSSLInputLimits::checkCamera(), images within the image limits and of one
// size (the CameraInfo's when it gives one), finite frame times and poses, increasing odometry stamps. A bad bag
// gives a vpException.
#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl_rosbag/vpSSLRosbagReader.h>

#include "fuzz_common.h"

namespace {
// A check of what the reader accepted: its vpException is a finding, not a rejection.
template <typename Check> void mustHold(Check check)
{
  try {
    check();
  } catch (const vpException &) {
    std::abort();
  }
}

// The first topic of one of the types, or "" when there is none.
std::string firstOf(const std::vector<vpSSLRosbagTopic> &topics, const char *type, const char *other = nullptr)
{
  for (const vpSSLRosbagTopic &t : topics) {
    if (t.type == type || (other != nullptr && t.type == other)) {
      return t.name;
    }
  }
  return std::string();
}

template <typename Type> void acquireAll(vpSSLRosbagReader &reader)
{
  vpSSLSequenceFrame frame;
  vpImage<Type> I;
  unsigned int w = reader.getImageWidth(), h = reader.getImageHeight();
  for (unsigned int n = 0; n < 4 && reader.acquire(frame, I); ++n) {
    mustHold([&I] { vpSSLInputLimits::checkImage(I, "fuzz_rosbag image"); });
    if (I.getWidth() == 0 || I.getHeight() == 0 || I.getWidth() > vpSSLInputLimits::maxImageSide() ||
        I.getHeight() > vpSSLInputLimits::maxImageSide()) {
      std::abort();
    }
    if (w == 0) {
      w = I.getWidth();
      h = I.getHeight();
    } else if (I.getWidth() != w || I.getHeight() != h) {
      std::abort();
    }
    if (frame.index != n || !std::isfinite(frame.t) || (n == 0 && frame.t != 0.)) {
      std::abort();
    }
    for (unsigned int i = 0; i < 6; ++i) {
      if (!std::isfinite(frame.oMv[i])) {
        std::abort();
      }
    }
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const std::filesystem::path path = sslfuzz::scratch() / "input.bag";
  sslfuzz::writeFile(path, data, size);
  // One reader for the whole run: open() closes the previous bag, and rosbag::Bag's construction (its plugin
  // loader) would otherwise take most of the time.
  static vpSSLRosbagReader reader;
  try {
    reader.open(path.string());
    const std::vector<vpSSLRosbagTopic> &topics = reader.getTopics();
    const std::string image = firstOf(topics, "sensor_msgs/Image", "sensor_msgs/CompressedImage");
    const std::string info = firstOf(topics, "sensor_msgs/CameraInfo");
    const std::string odometry = firstOf(topics, "nav_msgs/Odometry");
    // Odd sizes keep colour images in colour, even ones convert to grey: both paths of acquire().
    reader.setOdometryConvention(size % 4 < 2 ? vpSSLRosbagReader::ODOMETRY_REP103 : vpSSLRosbagReader::ODOMETRY_AS_IS);
    reader.selectTopics(image, info, odometry);
    mustHold([] { vpSSLInputLimits::checkCamera(reader.getCameraParameters(), "fuzz_rosbag CameraInfo"); });
    const vpSSLOdometryTrack &track = reader.getOdometry();
    for (size_t i = 1; i < track.size(); ++i) {
      if (!(track.getTime(i) > track.getTime(i - 1))) {
        std::abort();
      }
    }
    if (size % 2) {
      acquireAll<vpRGBa>(reader);
    } else {
      acquireAll<unsigned char>(reader);
    }
  } catch (const vpException &) {
  }
  return 0;
}
