/*!
  \file vpSSLCorpusPhotos.h
  \brief Real photographs of Debian's visp-images-data, as backgrounds and occluders of the corpus.
*/
#ifndef VP_SSL_CORPUS_PHOTOS_H
#define VP_SSL_CORPUS_PHOTOS_H

#include <string>
#include <vector>

#include <opencv2/core.hpp>

/*!
  \class vpSSLCorpusPhotos
  \ingroup group_ssl_bench
  \brief A fixed list of photographs from visp-images-data (Klimt, Solvay, the mire-2 and cube sequences, the mire
  and calibration grids; none with an AprilTag), each as a 512x512 linear RGB float image (centre square, sRGB
  decoded with gamma 2.2).
*/
class vpSSLCorpusPhotos
{
public:
  //! The directory of Debian's visp-images-data package.
  static std::string defaultDirectory();

  /*!
    Loads the list from \e directory. \return the number of photos read; 0 when the package is not installed
    (the corpus then draws no photo background; getMessage() says why).
  */
  size_t load(const std::string &directory = defaultDirectory());

  size_t size() const { return m_images.size(); }                   ///< Number of photos.
  const cv::Mat &get(size_t i) const { return m_images[i]; }        ///< Photo \e i (CV_32FC3, RGB, linear).
  const std::string &getName(size_t i) const { return m_names[i]; } ///< Its path relative to the directory.
  const std::string &getMessage() const { return m_message; }       ///< Why photos are missing, if they are.

private:
  std::vector<cv::Mat> m_images;
  std::vector<std::string> m_names;
  std::string m_message;
};

#endif
