/*!
  \file vpSSLBrightnessNormalizer.h
  \brief Brightness normalisation before matching (paper Sec. 5, Fig. 13).
*/
#ifndef VP_SSL_BRIGHTNESS_NORMALIZER_H
#define VP_SSL_BRIGHTNESS_NORMALIZER_H

#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLBrightnessNormalizer
  \ingroup group_ssl
  \brief Stretches the grey levels so that the matching function, which is proportional to contrast
  (paper Sec. 2.2.1), sees a hazy underwater image at full range.

  The grey levels between the low and high percentiles of the histogram are mapped linearly onto
  [0, 255] through a lookup table. The gain is capped (default 10) so that a nearly uniform image
  is not turned into amplified noise.

  \code
  vpSSLBrightnessNormalizer normalizer;   // 1 % and 99 % percentiles
  vpImage<unsigned char> In;
  normalizer.apply(I, In);
  \endcode
*/
class VISP_SSL_EXPORT vpSSLBrightnessNormalizer
{
public:
  vpSSLBrightnessNormalizer();

  //! Percentiles (in %) mapped to 0 and 255. \exception vpException unless 0 <= low < high <= 100.
  void setPercentiles(double low, double high);
  //! Largest gain applied (>= 1). \exception vpException if < 1.
  void setMaxGain(double gain);
  double getLowPercentile() const { return m_low; }   ///< Percentile mapped to 0.
  double getHighPercentile() const { return m_high; } ///< Percentile mapped to 255.
  double getMaxGain() const { return m_maxGain; }     ///< Largest gain applied.

  //! Normalises \e I into \e O (resized; may not alias \e I).
  void apply(const vpImage<unsigned char> &I, vpImage<unsigned char> &O) const;

  /*!
    The lookup table apply() uses, from the histogram of every \e step-th pixel of every \e step-th row
    of \e I (step 1: every pixel, what apply() does). A sparse histogram gives nearly the same percentiles
    for a fraction of the cost, and lets a caller normalise only the pixels it needs (regions of interest,
    a decimated image) with the same table whatever the region.
    \param I : grey image.
    \param lut : output, lut[g] is the normalised level of g.
    \param step : sampling step (>= 1). \exception vpException if 0.
  */
  void computeLut(const vpImage<unsigned char> &I, unsigned char lut[256], unsigned int step = 1) const;

private:
  double m_low;
  double m_high;
  double m_maxGain;
};

#endif
