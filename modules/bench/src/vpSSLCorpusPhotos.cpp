#include <visp3/ssl_bench/vpSSLCorpusPhotos.h>

#include <algorithm>
#include <cmath>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

std::string vpSSLCorpusPhotos::defaultDirectory()
{
  return VISP_SSL_IMAGES_DIR;
}

size_t vpSSLCorpusPhotos::load(const std::string &directory)
{
  static const char *kList[] = {"Klimt/Klimt.png",       "Solvay/Solvay_conference_1927_Version2_1024x705.png",
                                "mire-2/image.0001.pgm", "mire-2/image.0040.pgm",
                                "cube/image.0000.pgm",   "cube/image.0030.pgm",
                                "mire/mire.pgm",         "calibration/grid36-01.pgm",
                                "ellipse/ellipse.pgm"};
  m_images.clear();
  m_names.clear();
  m_message.clear();
  for (const char *name : kList) {
    cv::Mat img = cv::imread(directory + "/" + name, cv::IMREAD_COLOR);
    if (img.empty())
      continue;
    const int side = std::min(img.cols, img.rows);
    cv::Mat square = img(cv::Rect((img.cols - side) / 2, (img.rows - side) / 2, side, side));
    cv::Mat small, rgb, f;
    cv::resize(square, small, cv::Size(512, 512), 0., 0., side >= 512 ? cv::INTER_AREA : cv::INTER_LINEAR);
    cv::cvtColor(small, rgb, cv::COLOR_BGR2RGB);
    rgb.convertTo(f, CV_32FC3, 1. / 255.);
    cv::pow(f, 2.2, f); // sRGB to linear, approximately: the corpus adds light linearly
    m_images.push_back(f);
    m_names.push_back(name);
  }
  if (m_images.empty())
    m_message = "no photo read from " + directory +
                " (Debian package visp-images-data not installed?): photo "
                "backgrounds and occluders are replaced by sand";
  return m_images.size();
}
