/*!
  \file ssl_test_bag.h
  \brief The ROS 1 bag the rosbag tests write for themselves with rosbag_storage: rendered views of ssl3-a3,
  their CameraInfo and the vehicle's odometry (test_rosbag, write-test-bag for e2e/rosbag.sh).
*/
#ifndef SSL_TEST_BAG_H
#define SSL_TEST_BAG_H

#include <string>
#include <vector>

#include <nav_msgs/Odometry.h>
#include <opencv2/imgcodecs.hpp>
#include <ros/time.h>
#include <rosbag/bag.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpQuaternionVector.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

namespace ssltest {

//! What writeTestBag() wrote, for the checks.
struct TestBag
{
  vpCameraParameters cam{600., 600., 320., 240.};
  unsigned int width = 640, height = 480;
  std::vector<vpImage<unsigned char>> images;
  std::vector<double> imageTimes;                 //!< header stamps of the images (s)
  std::vector<double> odometryTimes;              //!< header stamps of the odometry messages (s)
  std::vector<vpHomogeneousMatrix> odometryPoses; //!< their pose.pose, in ROS's axes (REP 103)
  std::vector<vpHomogeneousMatrix> cMo;           //!< the target pose each image was rendered at
};

//! What writeTestBag() writes.
struct TestBagOptions
{
  unsigned int frames = 4;
  bool compressed = false; //!< sensor_msgs/CompressedImage (PNG) instead of sensor_msgs/Image (mono8)
  bool odometry = true;    //!< an /odom topic
  double odometryEnd = 0.; //!< when > 0, the odometry stops at this time after the first image
  std::string imageTopic = "/camera/image_raw";
  std::string infoTopic = "/camera/camera_info";
  std::string odometryTopic = "/odom";
  unsigned int width = 640;  //!< image width; the intrinsics scale with it (focal length 600 px at 640)
  unsigned int height = 480; //!< image height
};

/*!
  Writes \e filename: \e frames images of ssl3-a3 rendered 1.2 to 1.8 m ahead, 10 Hz from t = 1000.025 s, a
  CameraInfo per image, and odometry at 20 Hz from t = 1000 s (the images fall between two samples): the vehicle
  sails East at 0.5 m/s turning at 0.2 rad/s, 1 m below the surface (z = -1 in ROS's East-North-Up).
*/
inline TestBag writeTestBag(const std::string &filename, const TestBagOptions &options = TestBagOptions())
{
  ros::Time::init();
  TestBag out;
  out.width = options.width;
  out.height = options.height;
  const double scale = options.width / 640.;
  out.cam.initPersProjWithoutDistortion(600. * scale, 600. * scale, options.width / 2., options.height / 2.);
  vpSSLRenderer renderer(out.cam, out.width, out.height);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.setSupersampling(2);
  rosbag::Bag bag(filename, rosbag::bagmode::Write);
  const double t0 = 1000.;
  const double lastImage = t0 + 0.025 + 0.1 * (options.frames - 1);
  const double odometryEnd = options.odometryEnd > 0. ? t0 + 0.025 + options.odometryEnd : lastImage + 0.05;
  for (unsigned int k = 0; options.odometry && t0 + 0.05 * k <= odometryEnd + 1e-9; ++k) {
    const double t = t0 + 0.05 * k, yaw = 0.2 * (t - t0);
    nav_msgs::Odometry msg;
    msg.header.stamp = ros::Time(t);
    msg.header.frame_id = "odom";
    msg.child_frame_id = "base_link";
    msg.pose.pose.position.x = 0.5 * (t - t0);
    msg.pose.pose.position.y = 0.;
    msg.pose.pose.position.z = -1.;
    const vpQuaternionVector q(vpRotationMatrix(vpRxyzVector(0., 0., yaw)));
    msg.pose.pose.orientation.x = q.x();
    msg.pose.pose.orientation.y = q.y();
    msg.pose.pose.orientation.z = q.z();
    msg.pose.pose.orientation.w = q.w();
    bag.write(options.odometryTopic, msg.header.stamp, msg);
    out.odometryTimes.push_back(msg.header.stamp.toSec());
    out.odometryPoses.push_back(
        vpHomogeneousMatrix(vpTranslationVector(msg.pose.pose.position.x, 0., -1.), vpRotationMatrix(q)));
  }
  for (unsigned int i = 0; i < options.frames; ++i) {
    const ros::Time stamp(t0 + 0.025 + 0.1 * i);
    const vpHomogeneousMatrix cMo(0.05 * i, -0.03, 1.2 + 0.2 * i, 0.1, -0.15 * i, 0.05);
    vpImage<unsigned char> I;
    renderer.render(cMo, I);
    sensor_msgs::CameraInfo info;
    info.header.stamp = stamp;
    info.width = out.width;
    info.height = out.height;
    info.distortion_model = "plumb_bob";
    info.D.assign(5, 0.);
    info.K = {out.cam.get_px(), 0., out.cam.get_u0(), 0., out.cam.get_py(), out.cam.get_v0(), 0., 0., 1.};
    bag.write(options.infoTopic, stamp, info);
    if (options.compressed) {
      sensor_msgs::CompressedImage msg;
      msg.header.stamp = stamp;
      msg.format = "mono8; png compressed";
      cv::Mat mat;
      vpImageConvert::convert(I, mat);
      cv::imencode(".png", mat, msg.data);
      bag.write(options.imageTopic, stamp, msg);
    } else {
      sensor_msgs::Image msg;
      msg.header.stamp = stamp;
      msg.width = I.getWidth();
      msg.height = I.getHeight();
      msg.encoding = "mono8";
      msg.step = I.getWidth();
      msg.data.assign(I.bitmap, I.bitmap + I.getSize());
      bag.write(options.imageTopic, stamp, msg);
    }
    out.images.push_back(I);
    out.imageTimes.push_back(stamp.toSec());
    out.cMo.push_back(cMo);
  }
  bag.close();
  return out;
}

} // namespace ssltest

#endif
