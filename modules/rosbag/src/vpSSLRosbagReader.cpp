#include <visp3/ssl_rosbag/vpSSLRosbagReader.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include <cv_bridge/cv_bridge.h>
#include <nav_msgs/Odometry.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <ros/time.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpQuaternionVector.h>
#include <visp3/ssl/vpSSLInputLimits.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

#include "vpSSLRosbagCheck.h"

namespace {
const char *const kImage = "sensor_msgs/Image";
const char *const kCompressedImage = "sensor_msgs/CompressedImage";
const char *const kCameraInfo = "sensor_msgs/CameraInfo";
const char *const kOdometry = "nav_msgs/Odometry";

// REP 103 to the project's axes: world East-North-Up to North-East-Down (on the left), body forward-left-up to
// forward-starboard-down (on the right).
vpHomogeneousMatrix nedFromEnu()
{
  return vpHomogeneousMatrix(vpTranslationVector(), vpRotationMatrix({0, 1, 0, 1, 0, 0, 0, 0, -1}));
}

vpHomogeneousMatrix fluFromFrd()
{
  return vpHomogeneousMatrix(0., 0., 0., M_PI, 0., 0.);
}

// The message as \e Message, once its serialized bytes hold every string and array they declare
// (vpSSLRosbagCheck::checkMessage()): roscpp_serialization resizes an array to its declared length first. Null when
// the message is of another type (its md5sum differs).
template <typename Message>
typename Message::ConstPtr instantiate(const rosbag::MessageInstance &m, const std::string &at)
{
  std::vector<uint8_t> bytes(m.size());
  ros::serialization::OStream stream(bytes.data(), static_cast<uint32_t>(bytes.size()));
  m.write(stream);
  vpSSLRosbagCheck::checkMessage(ros::message_traits::datatype<Message>(), bytes.data(), bytes.size(), at);
  return m.instantiate<Message>();
}

// cv_bridge builds a matrix of height rows of step bytes on the message's data without comparing their sizes.
void checkImageData(const sensor_msgs::Image &msg, const std::string &at)
{
  vpSSLInputLimits::checkImageSize(msg.width, msg.height, at + "size");
  const uint64_t pixel = static_cast<uint64_t>(sensor_msgs::image_encodings::numChannels(msg.encoding)) *
                         ((sensor_msgs::image_encodings::bitDepth(msg.encoding) + 7) / 8);
  if (msg.step < msg.width * pixel)
    throw vpException(vpException::badValue, at + "step " + std::to_string(msg.step) + " shorter than a row of " +
                                                 std::to_string(msg.width) + " pixels of " + std::to_string(pixel) +
                                                 " bytes");
  if (static_cast<uint64_t>(msg.step) * msg.height > msg.data.size())
    throw vpException(vpException::badValue, at + "data of " + std::to_string(msg.data.size()) + " bytes, " +
                                                 std::to_string(msg.height) + " rows of " + std::to_string(msg.step) +
                                                 " expected");
}
} // namespace

class vpSSLRosbagReader::Impl
{
public:
  std::string filename;
  rosbag::Bag bag;
  bool isOpen = false;
  std::vector<vpSSLRosbagTopic> topics;
  std::string imageTopic;
  std::unique_ptr<rosbag::View> view;
  rosbag::View::iterator next;
  unsigned int index = 0;
  double firstTime = 0.;
  unsigned int width = 0, height = 0;

  std::string where(const std::string &topic) const { return filename + ": " + topic + ": "; }

  // The topic, which must be in the bag with one of the types and have a message.
  void checkTopic(const std::string &topic, const std::vector<std::string> &types) const
  {
    std::string ofType;
    for (const vpSSLRosbagTopic &t : topics) {
      if (t.name == topic) {
        if (std::find(types.begin(), types.end(), t.type) == types.end())
          throw vpException(vpException::badValue, where(topic) + "has type " + t.type + ", expected " + types[0] +
                                                       (types.size() > 1 ? " or " + types[1] : std::string()));
        if (t.count == 0)
          throw vpException(vpException::badValue, where(topic) + "no message on the topic");
        return;
      }
      if (std::find(types.begin(), types.end(), t.type) != types.end())
        ofType += (ofType.empty() ? "" : ", ") + t.name;
    }
    const std::string typeNames = types[0] + (types.size() > 1 ? " or " + types[1] : std::string());
    throw vpException(vpException::badValue, where(topic) + "no such topic in the bag (" + typeNames +
                                                 " topics: " + (ofType.empty() ? std::string("none") : ofType) + ")");
  }

  // The next image as an 8-bit grey or BGR matrix; false after the last one.
  bool read(cv::Mat &image, ros::Time &stamp)
  {
    if (!view || next == view->end())
      return false;
    const rosbag::MessageInstance &m = *next;
    const std::string at = where(imageTopic) + "image " + std::to_string(index) + ": ";
    try {
      if (m.getDataType() == kCompressedImage) {
        sensor_msgs::CompressedImage::ConstPtr msg = instantiate<sensor_msgs::CompressedImage>(m, at);
        if (!msg)
          throw vpException(vpException::badValue, at + "not a readable " + std::string(kCompressedImage));
        stamp = msg->header.stamp;
        // The size within the limits before OpenCV allocates it, and no line of libpng or libjpeg on stderr.
        try {
          vpSSLImageIo::checkData(msg->data, at + "compressed image");
        } catch (const vpException &e) {
          throw vpException(vpException::badValue, e.getStringMessage());
        }
        image = cv::imdecode(msg->data, cv::IMREAD_UNCHANGED);
        if (image.empty())
          throw vpException(vpException::badValue,
                            at + "cannot decode the compressed image (format \"" + msg->format + "\")");
        if (image.depth() != CV_8U)
          throw vpException(vpException::badValue, at + "not 8 bits per channel (format \"" + msg->format + "\")");
        if (image.channels() == 4)
          cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
      } else {
        sensor_msgs::Image::ConstPtr msg = instantiate<sensor_msgs::Image>(m, at);
        if (!msg)
          throw vpException(vpException::badValue, at + "not a readable " + std::string(kImage));
        checkImageData(*msg, at);
        stamp = msg->header.stamp;
        const bool colour = sensor_msgs::image_encodings::isColor(msg->encoding) ||
                            sensor_msgs::image_encodings::isBayer(msg->encoding);
        image = cv_bridge::toCvCopy(msg, colour ? "bgr8" : "mono8")->image;
      }
    } catch (const vpException &) {
      throw;
    } catch (const std::exception &e) {
      throw vpException(vpException::badValue, at + e.what());
    }
    if (stamp.isZero())
      throw vpException(vpException::badValue, at + "header stamp is 0 (the image's time is unknown)");
    const unsigned int w = static_cast<unsigned int>(image.cols), h = static_cast<unsigned int>(image.rows);
    if (width == 0) {
      width = w;
      height = h;
    } else if (w != width || h != height) {
      throw vpException(vpException::badValue, at + "size " + std::to_string(w) + "x" + std::to_string(h) +
                                                   ", expected " + std::to_string(width) + "x" +
                                                   std::to_string(height) + " (CameraInfo or first image)");
    }
    ++next;
    return true;
  }
};

vpSSLRosbagReader::vpSSLRosbagReader()
    : m_impl(new Impl), m_convention(ODOMETRY_REP103), m_width(0), m_height(0), m_imageCount(0)
{
  // rostime refuses to give any time before this (ros::TimeNotInitializedException).
  ros::Time::init();
}

vpSSLRosbagReader::~vpSSLRosbagReader()
{
  close();
}

void vpSSLRosbagReader::open(const std::string &filename)
{
  close();
  m_impl->filename = filename;
  // rosbag_storage trusts the lengths and offsets it reads: a corrupt bag is refused before it sees it.
  vpSSLRosbagCheck::checkBagFile(filename);
  try {
    m_impl->bag.open(filename, rosbag::bagmode::Read);
    m_impl->isOpen = true;
    rosbag::View all(m_impl->bag);
    for (const rosbag::ConnectionInfo *c : all.getConnections()) {
      auto same = [c](const vpSSLRosbagTopic &t) { return t.name == c->topic; };
      if (std::find_if(m_impl->topics.begin(), m_impl->topics.end(), same) != m_impl->topics.end())
        continue;
      vpSSLRosbagTopic topic;
      topic.name = c->topic;
      topic.type = c->datatype;
      topic.count = rosbag::View(m_impl->bag, rosbag::TopicQuery(c->topic)).size();
      m_impl->topics.push_back(topic);
    }
  } catch (const std::exception &e) {
    close();
    throw vpException(vpException::ioError, filename + ": cannot read the bag: " + e.what());
  }
  std::sort(m_impl->topics.begin(), m_impl->topics.end(),
            [](const vpSSLRosbagTopic &a, const vpSSLRosbagTopic &b) { return a.name < b.name; });
}

void vpSSLRosbagReader::close()
{
  m_impl->view.reset();
  if (m_impl->isOpen)
    m_impl->bag.close();
  m_impl->isOpen = false;
  m_impl->topics.clear();
  m_impl->index = 0;
  m_impl->width = m_impl->height = 0;
  m_width = m_height = m_imageCount = 0;
  m_odometry = vpSSLOdometryTrack();
}

const std::vector<vpSSLRosbagTopic> &vpSSLRosbagReader::getTopics() const
{
  return m_impl->topics;
}

void vpSSLRosbagReader::selectTopics(const std::string &imageTopic, const std::string &cameraInfoTopic,
                                     const std::string &odometryTopic)
{
  if (!m_impl->isOpen)
    throw vpException(vpException::notInitialized, "vpSSLRosbagReader: selectTopics() before open()");
  Impl &d = *m_impl;
  d.checkTopic(imageTopic, {kImage, kCompressedImage});
  d.checkTopic(cameraInfoTopic, {kCameraInfo});
  if (!odometryTopic.empty())
    d.checkTopic(odometryTopic, {kOdometry});
  try {
    // Intrinsics: the first CameraInfo message.
    rosbag::View infoView(d.bag, rosbag::TopicQuery(cameraInfoTopic));
    sensor_msgs::CameraInfo::ConstPtr info =
        instantiate<sensor_msgs::CameraInfo>(*infoView.begin(), d.where(cameraInfoTopic) + "message 0: ");
    if (!info)
      throw vpException(vpException::badValue, d.where(cameraInfoTopic) + "not a readable " + kCameraInfo);
    for (size_t i = 0; i < info->D.size(); ++i) {
      if (info->D[i] != 0.)
        throw vpException(vpException::badValue, d.where(cameraInfoTopic) + "distortion D[" + std::to_string(i) +
                                                     "] = " + std::to_string(info->D[i]) + " (" +
                                                     info->distortion_model +
                                                     "): not representable in ViSP's model; use the rectified "
                                                     "image topic and its CameraInfo with D = 0");
    }
    vpCameraParameters cam(info->K[0], info->K[4], info->K[2], info->K[5]);
    vpSSLInputLimits::checkCamera(cam, d.where(cameraInfoTopic) + "K");
    m_cam = cam;
    m_width = d.width = info->width;
    m_height = d.height = info->height;

    // Odometry: every message, at its header stamp.
    m_odometry = vpSSLOdometryTrack();
    if (!odometryTopic.empty()) {
      const vpHomogeneousMatrix nedMenu = nedFromEnu(), fluMfrd = fluFromFrd();
      unsigned int n = 0;
      for (const rosbag::MessageInstance &m : rosbag::View(d.bag, rosbag::TopicQuery(odometryTopic))) {
        const std::string at = d.where(odometryTopic) + "message " + std::to_string(n++) + ": ";
        nav_msgs::Odometry::ConstPtr odom = instantiate<nav_msgs::Odometry>(m, at);
        if (!odom)
          throw vpException(vpException::badValue, at + "not a readable " + kOdometry);
        const geometry_msgs::Pose &p = odom->pose.pose;
        const double position[3] = {p.position.x, p.position.y, p.position.z};
        for (int i = 0; i < 3; ++i) {
          if (!(std::fabs(position[i]) <= vpSSLOdometryTrack::maxTranslation()))
            throw vpException(vpException::badValue, at + "position." + "xyz"[i] + " " + std::to_string(position[i]) +
                                                         " is not finite or beyond +-1e7 m");
        }
        const vpQuaternionVector q(p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w);
        // Written so that a NaN element fails too.
        if (!(std::fabs(q.magnitude() - 1.) <= 1e-3))
          throw vpException(vpException::badValue, at + "orientation is not a unit quaternion");
        vpHomogeneousMatrix oMv(vpTranslationVector(p.position.x, p.position.y, p.position.z),
                                vpRotationMatrix(vpQuaternionVector(q.x() / q.magnitude(), q.y() / q.magnitude(),
                                                                    q.z() / q.magnitude(), q.w() / q.magnitude())));
        if (m_convention == ODOMETRY_REP103)
          oMv = nedMenu * oMv * fluMfrd;
        try {
          m_odometry.add(odom->header.stamp.toSec(), oMv);
        } catch (const vpException &e) {
          throw vpException(vpException::badValue, at + e.getStringMessage());
        }
      }
    }

    d.imageTopic = imageTopic;
    d.view.reset(new rosbag::View(d.bag, rosbag::TopicQuery(imageTopic)));
    d.next = d.view->begin();
    d.index = 0;
    m_imageCount = d.view->size();
  } catch (const vpException &) {
    throw;
  } catch (const std::exception &e) {
    throw vpException(vpException::ioError, d.filename + ": cannot read the bag: " + e.what());
  }
}

void vpSSLRosbagReader::fill(vpSSLSequenceFrame &frame, double t)
{
  frame = vpSSLSequenceFrame();
  frame.index = m_impl->index++;
  if (frame.index == 0)
    m_impl->firstTime = t;
  try {
    m_odometry.stampFrame(t, m_impl->firstTime, frame);
  } catch (const vpException &e) {
    throw vpException(vpException::badValue, m_impl->where(m_impl->imageTopic) + "image " +
                                                 std::to_string(frame.index) + ": " + e.getStringMessage());
  }
}

template <typename Type> bool vpSSLRosbagReader::acquireImage(vpSSLSequenceFrame &frame, vpImage<Type> &I)
{
  cv::Mat image;
  ros::Time stamp;
  if (!m_impl->read(image, stamp))
    return false;
  fill(frame, stamp.toSec());
  vpImageConvert::convert(image, I);
  return true;
}

bool vpSSLRosbagReader::acquire(vpSSLSequenceFrame &frame, vpImage<unsigned char> &I)
{
  return acquireImage(frame, I);
}

bool vpSSLRosbagReader::acquire(vpSSLSequenceFrame &frame, vpImage<vpRGBa> &I)
{
  return acquireImage(frame, I);
}
