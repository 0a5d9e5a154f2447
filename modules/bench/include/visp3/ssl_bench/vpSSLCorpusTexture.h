/*!
  \file vpSSLCorpusTexture.h
  \brief A planar texture with its mip pyramid, sampled without aliasing at any minification.
*/
#ifndef VP_SSL_CORPUS_TEXTURE_H
#define VP_SSL_CORPUS_TEXTURE_H

#include <vector>

#include <opencv2/core.hpp>

/*!
  \class vpSSLCorpusTexture
  \ingroup group_ssl_bench
  \brief An image laid on a plane (metres) with its mip pyramid, sampled trilinearly.

  Pixel (c, r) of level 0 covers the square of side 1 / getPixelsPerMetre() whose centre is at plane point
  (x0 + (c + 0.5) / ppm, y0 + (r + 0.5) / ppm). Each level is the 2x2 box average of the one below (the level-0
  image is padded to a multiple of the coarsest level's factor so that every halving is exact). sample() picks the
  two levels whose pixel is between 0.75 and 3 times the sample's footprint and blends them, so a level is never
  minified by more than 1.5 (a distant sheet does not alias) and the step between levels leaves no seam.
*/
class vpSSLCorpusTexture
{
public:
  //! How a plane point outside the image is read.
  enum Border
  {
    CLAMP,  ///< The nearest edge pixel (a sheet: its outside is cut by a mask anyway).
    MIRROR, ///< The image mirrored at its edges, repeated over the whole plane (a seabed texture).
  };

  vpSSLCorpusTexture() = default;

  /*!
    Sets the level-0 image (CV_32FC1 or CV_32FC3) and where it lies on the plane, and builds the pyramid down to
    a level of about 8 pixels. \e pad is the value of the padding pixels (every channel).
    \exception vpException on an empty image, another type, or a non-positive density.
  */
  void set(const cv::Mat &image, double x0, double y0, double pixelsPerMetre, Border border, float pad = 1.f);

  /*!
    Value at plane point (\e x, \e y) for a sample whose footprint on the plane is \e footprint metres (the
    largest extent of one output sample): trilinear between the two levels around that footprint. \e out receives
    getChannels() values.
  */
  void sample(double x, double y, double footprint, float *out) const { sampleLevel(x, y, level(footprint), out); }

  /*!
    The fractional pyramid level for a sample footprint of \e footprint metres: between the level minified by 0.75
    to 1.5 and the next one (what sample() reads). A caller whose samples share a footprint computes it once.
  */
  double level(double footprint) const;

  //! Value at plane point (\e x, \e y) read trilinearly at fractional \e level (from level()).
  void sampleLevel(double x, double y, double level, float *out) const;

  int getChannels() const { return m_channels; }                  ///< 1 or 3.
  double getPixelsPerMetre() const { return m_ppm; }              ///< Level-0 density (px/m).
  size_t getNbLevels() const { return m_levels.size(); }          ///< Number of pyramid levels.
  const cv::Mat &getLevel(size_t i) const { return m_levels[i]; } ///< Pyramid level \e i (0: full resolution).
  bool empty() const { return m_levels.empty(); }                 ///< Whether set() was called.

private:
  void bilinear(size_t level, double c, double r, float *out) const;

  std::vector<cv::Mat> m_levels;
  double m_x0 = 0., m_y0 = 0., m_ppm = 1.;
  int m_channels = 0;
  Border m_border = CLAMP;
};

#endif
