//! \example tutorial-ssl-rosbag.cpp
//! Lists the topics of a ROS 1 bag, or converts its images, camera intrinsics and odometry into a recorded
//! sequence with vpSSLRosbagReader (doc/recordings.md).
#include <iomanip>
#include <iostream>
#include <string>

#include <visp3/ssl_io/vpSSLSequenceWriter.h>
#include <visp3/ssl_rosbag/vpSSLRosbagReader.h>

#include "ssl_recording_common.h"
#include "ssl_tutorial_common.h"
#include "ssl_tutorial_option_loop.h"

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-rosbag --bag FILE --list
       tutorial-ssl-rosbag --bag FILE --image-topic T --info-topic T [--odometry-topic T] --output DIR [options]

Reads a ROS 1 bag with vpSSLRosbagReader: --list prints its topics (name, type, messages);
otherwise the images of one topic (sensor_msgs/Image or sensor_msgs/CompressedImage, converted to
8 bits: grey or colour), the intrinsics of the first sensor_msgs/CameraInfo message of another and,
optionally, the nav_msgs/Odometry poses interpolated to each image's header stamp become a
recorded sequence (doc/sequence-format.md) for tutorial-ssl-tracker and tutorial-ssl-vs-apriltag.
See doc/recordings.md.

Options:
  --bag FILE            ROS 1 bag (format 2.0). Required.
  --list                Print the topics and exit.
  --image-topic T       Image topic. Required to convert.
  --info-topic T        sensor_msgs/CameraInfo topic of the same camera. Required to convert. Its
                        distortion must be 0 (use the rectified image topic).
  --odometry-topic T    nav_msgs/Odometry topic; it must cover the time of every image (no
                        extrapolation). Needs --camera-to-vehicle.
  --odometry-axes A     rep103 (default: ROS's East-North-Up world and forward-left-up body,
                        turned into the project's North-East-Down and forward-starboard-down) or
                        ned (already the project's axes, kept as they are).
  --camera-to-vehicle "TX TY TZ TUX TUY TUZ"
                        vMc, the camera's pose in the vehicle frame (m, theta-u rad), in the
                        project's vehicle axes. Required with --odometry-topic; without, 0 0 0 0 0 0
                        is written (the tracker uses it only with odometry).
  --target NAME         Target of sequence.json (default ssl3-a3).
  --output DIR          Sequence folder written. It must not exist or be empty.
  --max-frames N        Convert the first N images only, 1 to 100000000 (default: all).
  --help                This help.

Exit status: 0 on success; 1 when the bag cannot be read, a topic is not in it (the message lists
the topics of the right type) or has another type, the CameraInfo is not usable, an image cannot
be decoded or the odometry does not cover it, the output folder is not empty, or a write error (the
frames written before an error are a valid sequence); 2 on a bad option. Every error is one line
on stderr.
)";

const char *kProgram = "tutorial-ssl-rosbag";

int run(int argc, char **argv)
{
  std::string bag, imageTopic, infoTopic, odometryTopic;
  bool list = false;
  ssltut::RecordingOptions recording;
  vpSSLRosbagReader::vpOdometryConvention axes = vpSSLRosbagReader::ODOMETRY_REP103;
  long long maxFrames = -1;
  // One option: false for an option this tutorial does not know.
  const auto option = [&](const std::string &a, const auto &value) {
    if (recording.parse(a, value)) {
    } else if (a == "--bag") {
      bag = value();
    } else if (a == "--list") {
      list = true;
    } else if (a == "--image-topic") {
      imageTopic = value();
    } else if (a == "--info-topic") {
      infoTopic = value();
    } else if (a == "--odometry-topic") {
      odometryTopic = value();
    } else if (a == "--odometry-axes") {
      const std::string v = value();
      if (v != "rep103" && v != "ned") {
        throw ssltut::UsageError("option --odometry-axes: expected rep103 or ned, got \"" + v + "\"");
      }
      axes = v == "ned" ? vpSSLRosbagReader::ODOMETRY_AS_IS : vpSSLRosbagReader::ODOMETRY_REP103;
    } else if (a == "--max-frames") {
      maxFrames = ssltut::parseInteger("option " + a, value(), 1, 100000000);
    } else {
      return false;
    }
    return true;
  };
  if (!ssltut::readOptions(argc, argv, kUsage, ssltut::OptionStyle::HelpFirst, option)) {
    return 0; // --help
  }
  if (bag.empty()) {
    throw ssltut::UsageError("--bag is required (see --help)");
  }
  if (!list && (imageTopic.empty() || infoTopic.empty() || recording.output.empty())) {
    throw ssltut::UsageError("--image-topic, --info-topic and --output are required to convert (or --list)");
  }
  recording.checkMount(!odometryTopic.empty(), "--odometry-topic");

  if (!list) {
    ssltut::checkNewOutput(recording.output);
  }
  vpSSLRosbagReader reader;
  reader.setOdometryConvention(axes);
  reader.open(bag);
  if (list) {
    std::cout << std::left << std::setw(40) << "topic"
              << " " << std::setw(32) << "type"
              << " messages" << std::endl;
    for (const vpSSLRosbagTopic &t : reader.getTopics()) {
      std::cout << std::left << std::setw(40) << t.name << " " << std::setw(32) << t.type << " " << t.count
                << std::endl;
    }
    return 0;
  }

  reader.selectTopics(imageTopic, infoTopic, odometryTopic);
  vpSSLSequenceWriter writer;
  writer.open(recording.output, reader.getCameraParameters(), recording.info(), {vpSSLOdometryTrack::stampColumn()});
  vpSSLSequenceFrame frame;
  vpImage<vpRGBa> I;
  while ((maxFrames < 0 || writer.getFrameCount() < maxFrames) && reader.acquire(frame, I)) {
    writer.write(frame, I);
  }
  writer.close();
  std::cout << kProgram << ": " << writer.getFrameCount() << " frames of " << imageTopic << " written to "
            << recording.output << (odometryTopic.empty() ? " without odometry" : " with odometry of " + odometryTopic)
            << std::endl;
  return 0;
}
} // namespace

int main(int argc, char **argv)
{
  return ssltut::guardedMain(kProgram, [&] { return run(argc, argv); });
}
