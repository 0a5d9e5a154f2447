/*!
  \file vpSSLLandmark.h
  \brief One circular self-similar landmark found in an image.
*/
#ifndef VP_SSL_LANDMARK_H
#define VP_SSL_LANDMARK_H

#include <visp3/core/vpImagePoint.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \struct vpSSLLandmark
  \ingroup group_ssl
  \brief A landmark seen in the image: centre, apparent size and matching score.

  The outer circle of a landmark projects to an ellipse of semi-axes a >= b, the major axis at angle
  \e theta from the u axis. \e radius is the major semi-axis, the apparent radius that Eq. 6 turns
  into a range (it does not shrink with the tilt of the target). The eight directional radii, along
  0, 45, ..., 315 degrees from the u axis (v down), are what the ellipse was fitted to; a direction
  whose ring pattern could not be read (occlusion, image border) holds 0.
*/
struct VISP_SSL_EXPORT vpSSLLandmark
{
  double u = 0.;           ///< Centre column (px, sub-pixel, pixel centres at integers).
  double v = 0.;           ///< Centre row (px).
  double radius = 0.;      ///< Apparent outer radius: major semi-axis of the outer ellipse (px).
  double minorRadius = 0.; ///< Minor semi-axis of the outer ellipse (px).
  double theta = 0.;       ///< Angle of the major axis from the u axis (rad, towards +v).
  double score = 0.;       ///< Matching function at the centre, normalised to [0, 1] (paper Eq. 5).
  double radiusEq7 = 0.;   ///< The paper's estimate: argmax over w of the +x matching sum (Eq. 7), in px; 0 unless
                           ///< vpSSLDetector::setRadiusSweep().
  double directionalRadius[8] = {0., 0., 0., 0.,
                                 0., 0., 0., 0.}; ///< Outer radius along each of 8 directions (px), 0 if unread.
  unsigned int nbDirections = 0;                  ///< How many of the 8 directions showed the ring pattern.

  //! Centre as a vpImagePoint (i = v, j = u).
  vpImagePoint getCenter() const { return vpImagePoint(v, u); }
};

#endif
