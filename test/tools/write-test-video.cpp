// Writes the e2e tests' video (test/e2e/record.sh) with OpenCV: ssl3-a3 rendered by vpSSLRenderer through the
// camera of CAMERA_XML, approaching from 2 m to 0.8 m, as an MJPG AVI.
//   write-test-video OUT.avi CAMERA_XML FRAMES FPS
#include <cstdlib>
#include <iostream>

#include <opencv2/videoio.hpp>

#include <visp3/core/vpImageConvert.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>

int main(int argc, char **argv)
{
  if (argc != 5) {
    std::cerr << "usage: write-test-video OUT.avi CAMERA_XML FRAMES FPS" << std::endl;
    return 2;
  }
  unsigned int width = 0, height = 0;
  const vpCameraParameters cam = vpSSLCameraFile::load(argv[2], "Camera", &width, &height);
  const int frames = std::atoi(argv[3]);
  vpSSLRenderer renderer(cam, width, height);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  renderer.setSupersampling(2);
  cv::VideoWriter video(argv[1], cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), std::atof(argv[4]),
                        cv::Size(static_cast<int>(width), static_cast<int>(height)), false);
  if (!video.isOpened()) {
    std::cerr << "write-test-video: cannot write " << argv[1] << std::endl;
    return 1;
  }
  for (int i = 0; i < frames; ++i) {
    const double z = 2. - 1.2 * i / (frames > 1 ? frames - 1 : 1);
    vpImage<unsigned char> I;
    renderer.render(vpHomogeneousMatrix(0.02, -0.01, z, 0.15, -0.1, 0.05), I);
    cv::Mat mat;
    vpImageConvert::convert(I, mat);
    video.write(mat);
  }
  return 0;
}
