/*!
  \file vpSSLPattern.h
  \brief The self-similar square wave (paper Eq. 1) and the two landmark patterns built on it.
*/
#ifndef VP_SSL_PATTERN_H
#define VP_SSL_PATTERN_H

#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLPattern
  \ingroup group_ssl
  \brief Intensity of the printed self-similar patterns.

  The square wave \f$ s_p(x) = \lfloor 2(\log_p x - \lfloor \log_p x \rfloor) \rfloor \f$ (paper Eq. 1)
  is 0 (black) or 1 (white). The circular landmark of Fig. 1(b) paints \f$ s_p(\rho / R) \f$ inside its
  outer radius \f$ R \f$ (paper Eq. 4); the original linear landmark of Briggs et al. (Fig. 1a) paints
  \f$ s_p(x / L) \f$ for \f$ x \in (0, L] \f$, constant along the other axis.

  \code
  int black = vpSSLPattern::squareWave(0.9, 0.5); // 0: the outermost ring is black
  int white = vpSSLPattern::squareWave(0.6, 0.5); // 1
  \endcode
*/
class VISP_SSL_EXPORT vpSSLPattern
{
public:
  /*!
    Self-similar square wave (Eq. 1).
    \param x : normalised abscissa in (0, 1]; values <= 0 return 1 (the centre, where rings are
    thinner than any print, is treated as white).
    \param p : similarity ratio in (0, 1).
    \return 0 for black, 1 for white.
  */
  static int squareWave(double x, double p);

  /*!
    Circular landmark (Eq. 4): value at offset (dx, dy) from the centre of a landmark of outer radius
    \e radius; -1 outside the landmark (the caller paints the background).
  */
  static int circular(double dx, double dy, double radius, double p);

  /*!
    Original linear landmark of Briggs et al.: value at abscissa \e x from the pattern's origin for a
    pattern of length \e length; -1 outside (0, length].
  */
  static int linear(double x, double length, double p);
};

#endif
