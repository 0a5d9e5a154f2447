/*
  Private to vpSSLDetector: the grey level of a landmark's centre disc between those of its two outer rings, the test
  that tells a small landmark from round clutter whose outer rings look like one's (vpSSLDetectionPipeline).
*/
#ifndef VP_SSL_CENTRE_TONE_H
#define VP_SSL_CENTRE_TONE_H

#include <visp3/core/vpImage.h>

#include <visp3/ssl/vpSSLLandmark.h>

namespace vpSSLCentreTone {
/*
  The printed rings inside R p^1.5 (p the similarity ratio) are white on 1 / (1 + p) of that disc's area (2 / 3 for
  p = 0.5): the outermost of them is white and each ring pair shrinks by p. Sharp and face-on, the mean level of the
  disc lies that far from the level of the outer black ring (from sqrt(p) R to R) to that of the white ring inside it
  (from p R to sqrt(p) R). Blur greys the white ring more than the disc, which can take the disc's tone past 1, but
  leaves it above the black ring's level while the rings are resolved (a minor semi-axis of 4 blur sigmas or more,
  test_centre_tone). A bull's-eye whose outer rings pass for a landmark's may end in a solid dark disc, and a dark
  speck ringed in light is dark at its centre: their tone lies below 0.

  \e tone is (centre - black) / (white - black), each level the mean of bilinear samples about the ellipses of
  \e landmark's shape (its centre, radius, minorRadius and theta) over a band of relative radii: the centre disc to
  0.85 p^1.5, the white ring from 1.06 p to 0.96 sqrt(p), the black ring from 1.05 sqrt(p) to 0.96 (0.3, 0.53-0.68
  and 0.74-0.96 for p = 0.5: clear of the printed edges by a few tenths of a ring).
  \return false (\e tone untouched) if a sample leaves the image, the landmark's axes are not positive and finite, or
  the two rings' levels differ by less than a grey level.
*/
bool measure(const vpImage<unsigned char> &I, const vpSSLLandmark &landmark, double p, double &tone);
} // namespace vpSSLCentreTone

#endif
