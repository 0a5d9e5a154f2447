// Writes the test video of the video e2e checks (video.sh) with OpenCV's cv::VideoWriter: ssl3-a3 rendered by
// vpSSLRenderer through data/camera/camera-640x480.xml's camera (px = py = 554.3), approached from 1.4 m to
// 0.7 m with a 20 degree tilt, MJPG in an AVI at 10 fps.
// Usage: write_video OUT.avi FRAMES
#include <cstdlib>
#include <iostream>
#include <string>

#include <opencv2/videoio.hpp>

#include <visp3/core/vpImageConvert.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

int main(int argc, char **argv)
{
  const int frames = argc == 3 ? std::atoi(argv[2]) : 0;
  if (frames < 2 || frames > 1000) {
    std::cerr << "usage: write_video OUT.avi FRAMES (2 to 1000)" << std::endl;
    return 2;
  }
  const vpCameraParameters cam(554.3, 554.3, 320., 240.);
  vpSSLRenderer renderer(cam, 640, 480);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  cv::VideoWriter writer(argv[1], cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10., cv::Size(640, 480), false);
  if (!writer.isOpened()) {
    std::cerr << "write_video: " << argv[1] << ": cannot open for writing" << std::endl;
    return 1;
  }
  for (int k = 0; k < frames; ++k) {
    const double range = 1.4 - 0.7 * k / (frames - 1);
    const vpHomogeneousMatrix cMo(0.02, -0.01, range, vpMath::rad(20.), vpMath::rad(5.), vpMath::rad(10.));
    vpImage<unsigned char> I;
    renderer.render(cMo, I);
    cv::Mat frame;
    vpImageConvert::convert(I, frame);
    writer.write(frame);
  }
  writer.release();
  return 0;
}
