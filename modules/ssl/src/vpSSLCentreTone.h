/*
  Private to vpSSLDetector: the grey levels of a landmark's centre between those of its two outer rings, the tests that
  tell a small landmark from round clutter whose outer rings look like one's (vpSSLDetectionPipeline).
*/
#ifndef VP_SSL_CENTRE_TONE_H
#define VP_SSL_CENTRE_TONE_H

#include <visp3/core/vpImage.h>

#include <visp3/ssl/vpSSLLandmark.h>

namespace vpSSLCentreTone {
/*
  What measure() reads inside a landmark, each level relative to the outer rings: (level - black) / (white - black).

  \e tone: the centre disc to R p^1.5 (p the similarity ratio). The printed rings inside it are white on 1 / (1 + p)
  of its area (2 / 3 for p = 0.5): the outermost of them is white and each ring pair shrinks by p. Sharp and face-on,
  the mean level of the disc lies that far from the level of the outer black ring (from sqrt(p) R to R) to that of
  the white ring inside it (from p R to sqrt(p) R). Blur greys the white ring more than the disc, which can take the
  disc's tone past 1, but leaves it above the black ring's level while the rings are resolved (a minor semi-axis of 4
  blur sigmas or more, test_centre_tone). A bull's-eye whose outer rings pass for a landmark's may end in a solid dark
  disc, and a dark speck ringed in light is dark at its centre: their tone lies below 0.

  \e rise: how much lighter than the core (the disc to R p^3, whose finest rings are white on p / (1 + p) of it, a
  third for p = 0.5) the band about the printed edge at R p^2 is (from 0.8 p^2 to 1.2 p^2: half black, half white). On
  a landmark the two are close: sharp, the band is the lighter by a sixth; blurred, both tend to one grey. A bull's-eye
  of rings of one width ending in a dark dot, its outer rings passing for a landmark's, has a light ring across that
  band and its dark dot in the core: its rise is over 1 (1.3 to 2.6 on the corpus's negatives), a landmark's 0.8 at
  most. \e riseError combines (in quadrature) the spreads of the band's and the core's levels over eight sectors about
  the landmark, each over sqrt(8), in the same units: the rise's standard error were the sectors independent. They share
  the core's few pixels, so it understates the noise (0.4 of the rise's spread on a faint drawn landmark,
  test_centre_tone), but it grows with it: on a faint landmark of a few grey levels, noise alone can lift the rise
  over 1.
*/
struct Reading
{
  double tone;
  double rise;
  double riseError;
  double coreMinor; //!< The core's minor semi-axis (px): 0.85 p^3 of the landmark's.
};

/*
  Reads \e reading about the ellipses of \e landmark's shape (its centre, radius, minorRadius and theta), each level
  the mean of bilinear samples over a band of relative radii: the centre disc to 0.85 p^1.5, the core to 0.85 p^3,
  the band from 0.8 p^2 to 1.2 p^2, the white ring from 1.06 p to 0.96 sqrt(p), the black ring from 1.05 sqrt(p) to
  0.96 (0.3, 0.106, 0.2-0.3, 0.53-0.68 and 0.74-0.96 for p = 0.5: the rings' bands clear of the printed edges by a few
  tenths of a ring).
  \return false (\e reading untouched) if a sample leaves the image, the landmark's axes are not positive and finite,
  or the two rings' levels differ by less than a grey level.
*/
bool measure(const vpImage<unsigned char> &I, const vpSSLLandmark &landmark, double p, Reading &reading);
} // namespace vpSSLCentreTone

#endif
