/*!
  \file vpSSLRosbagReader.h
  \brief Reader of ROS 1 bag files: images, camera intrinsics and odometry, frame by frame.
*/

#ifndef VP_SSL_ROSBAG_READER_H
#define VP_SSL_ROSBAG_READER_H

#include <memory>
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl_io/vpSSLOdometryTrack.h>
#include <visp3/ssl_io/vpSSLSequenceFrame.h>

/*!
  \struct vpSSLRosbagTopic
  \ingroup group_ssl_rosbag
  \brief One topic of a bag, as vpSSLRosbagReader::getTopics() lists it.
*/
struct VISP_SSL_EXPORT vpSSLRosbagTopic
{
  std::string name;       ///< Topic name, e.g. "/camera/image_raw".
  std::string type;       ///< Message type, e.g. "sensor_msgs/Image".
  unsigned int count = 0; ///< Number of messages on the topic.
};

/*!
  \class vpSSLRosbagReader
  \ingroup group_ssl_rosbag
  \brief Reads a ROS 1 bag (rosbag format 2.0) as a recorded sequence: the images of one \c sensor_msgs/Image or
  \c sensor_msgs/CompressedImage topic, the intrinsics of the first \c sensor_msgs/CameraInfo message of another,
  and optionally the vehicle poses of a \c nav_msgs/Odometry topic interpolated to each image's time
  (vpSSLOdometryTrack). Library \c visp_ssl_rosbag (built when CMake finds Debian's ROS packages); the
  conversion to a sequence folder is tutorial-ssl-rosbag, the format and its limits are in doc/recordings.md.

  Frames are stamped by vpSSLOdometryTrack::stampFrame(): \c t counts from the first image's header stamp, the
  extra \c stamp holds the stamp itself, and \c oMv has its origin at the first odometry sample's position. Intrinsics
  are \c K's \c fx, \c fy, \c cx, \c cy; a CameraInfo with a non-zero distortion coefficient is refused (ViSP's
  one-coefficient model is not \c plumb_bob): use the rectified image topic. Odometry is \c pose.pose of each message at
  its header stamp; with ODOMETRY_REP103 (default) it is turned from ROS's axes (REP 103: world East-North-Up, body x
  forward, y left, z up) into the project's (world North-East-Down, body x forward, y starboard, z down).

  The frames feed the tracker directly:
  \code
  vpSSLRosbagReader reader;
  reader.open("dive.bag");
  reader.selectTopics("/camera/image_raw", "/camera/camera_info", "/odom");
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), reader.getCameraParameters(), vMc);
  vpSSLSequenceFrame frame;
  vpImage<unsigned char> I;
  while (reader.acquire(frame, I)) {
    tracker.track(I, vpHomogeneousMatrix(frame.oMv));
  }
  \endcode
*/
class VISP_SSL_EXPORT vpSSLRosbagReader
{
public:
  //! The axes of the odometry messages.
  enum vpOdometryConvention
  {
    ODOMETRY_REP103, ///< ROS's REP 103: world East-North-Up, body forward-left-up; converted to NED and FRD.
    ODOMETRY_AS_IS   ///< Already the project's (world North-East-Down, body forward-starboard-down): kept as is.
  };

  //! A closed reader; call open().
  vpSSLRosbagReader();
  //! Closes the bag.
  ~vpSSLRosbagReader();
  vpSSLRosbagReader(const vpSSLRosbagReader &) = delete;
  vpSSLRosbagReader &operator=(const vpSSLRosbagReader &) = delete;

  /*!
    Opens a bag and lists its topics (getTopics()).
    \exception vpException (ioError) naming the file when it cannot be opened or is not a readable bag.
  */
  void open(const std::string &filename);
  //! Closes the bag; open() may be called again.
  void close();
  //! The bag's topics, sorted by name.
  const std::vector<vpSSLRosbagTopic> &getTopics() const;

  //! Axes of the odometry messages (default ODOMETRY_REP103); set before selectTopics().
  void setOdometryConvention(vpOdometryConvention convention) { m_convention = convention; }
  //! See setOdometryConvention().
  vpOdometryConvention getOdometryConvention() const { return m_convention; }

  /*!
    Chooses the topics, reads the camera intrinsics and the odometry, and places the reader before the first
    image.
    \param imageTopic : a sensor_msgs/Image or sensor_msgs/CompressedImage topic.
    \param cameraInfoTopic : a sensor_msgs/CameraInfo topic; its first message gives the intrinsics.
    \param odometryTopic : a nav_msgs/Odometry topic, or empty for none.
    \exception vpException (badValue) <tt>BAG: TOPIC: problem</tt> when a topic is not in the bag (the message
    lists those of the right type), has another type or no message, when the intrinsics are not usable or an
    odometry stamp does not increase.
  */
  void selectTopics(const std::string &imageTopic, const std::string &cameraInfoTopic,
                    const std::string &odometryTopic = std::string());

  //! Camera intrinsics of the CameraInfo topic (valid after selectTopics()).
  const vpCameraParameters &getCameraParameters() const { return m_cam; }
  //! Image width of the CameraInfo message (0 when it gives none).
  unsigned int getImageWidth() const { return m_width; }
  //! Image height of the CameraInfo message (0 when it gives none).
  unsigned int getImageHeight() const { return m_height; }
  //! Number of images on the image topic.
  unsigned int getImageCount() const { return m_imageCount; }
  //! The odometry samples (empty without an odometry topic).
  const vpSSLOdometryTrack &getOdometry() const { return m_odometry; }

  /*!
    Reads the next image, converted to grey, and fills \e frame: \c index (counted from 0), \c t (s, from the first
    image's header stamp), \c extras["stamp"] (the header stamp) and, with an odometry topic, \c oMv (see the class
    description).
    \return false after the last image.
    \exception vpException (badValue) <tt>BAG: TOPIC: image N: problem</tt> on an image that cannot be decoded,
    has a size other than the CameraInfo's or the first image's, a zero stamp, or a time the odometry does not
    cover.
  */
  bool acquire(vpSSLSequenceFrame &frame, vpImage<unsigned char> &I);
  //! As acquire(vpSSLSequenceFrame &, vpImage<unsigned char> &), keeping colour images in colour.
  bool acquire(vpSSLSequenceFrame &frame, vpImage<vpRGBa> &I);

private:
  class Impl;
  void fill(vpSSLSequenceFrame &frame, double t);
  template <typename Type> bool acquireImage(vpSSLSequenceFrame &frame, vpImage<Type> &I);
  std::unique_ptr<Impl> m_impl;
  vpOdometryConvention m_convention;
  vpCameraParameters m_cam;
  unsigned int m_width;
  unsigned int m_height;
  unsigned int m_imageCount;
  vpSSLOdometryTrack m_odometry;
};

#endif
