/*!
  \file vpSSLPoseHypothesis.h
  \brief One candidate pose of the target from a single frame.
*/
#ifndef VP_SSL_POSE_HYPOTHESIS_H
#define VP_SSL_POSE_HYPOTHESIS_H

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \struct vpSSLPoseHypothesis
  \ingroup group_ssl
  \brief A pose of the target consistent with one image (paper Sec. 3.2), with how well it explains it.

  With three landmarks, P3P has up to four solutions that all put the centres exactly where they are
  seen; the paper leaves the choice to the tracker. The ellipse and depth errors measure what the
  centres do not: the apparent size (Eq. 6) and the shape of each landmark's outer ellipse predicted
  by the hypothesis against the detected ones. vpSSLPoseEstimator returns the hypotheses best first.
*/
struct VISP_SSL_EXPORT vpSSLPoseHypothesis
{
  /*!
    Target pose in the camera frame. For a position-only hypothesis (\e positionOnly), its translation is
    the centre of the landmark \e landmark (not the target origin, which cannot be placed without the
    orientation) and its rotation is the identity: the target plane facing the camera, parallel to the
    image plane, as the paper assumes for Eq. 6.
  */
  vpHomogeneousMatrix cMo;
  double reprojectionError = 0.; ///< RMS distance between the detected and the projected centres (px).
  /*!
    Mean over the landmarks of the relative difference between the detected outer ellipse and the one
    the hypothesis predicts (Frobenius norm of the difference of their 2x2 shape matrices over that of
    the detected one); 0 is a perfect agreement.
  */
  double ellipseError = 0.;
  double depthError = 0.;       ///< Mean relative difference between each landmark's depth and its Eq. 6 depth.
  double cost = 0.;             ///< Ranking cost (lower is better), see vpSSLPoseEstimator.
  unsigned int nbLandmarks = 0; ///< Landmarks used.
  int landmark = -1;            ///< For a position-only hypothesis, the target landmark whose centre cMo holds.
  bool positionOnly = false;    ///< True when fewer than three landmarks were seen (paper cases 1 and 2).
  bool refined = false;         ///< True when the virtual visual servoing refinement (vpPose) succeeded.

  // How a particle filter spreads its particles around this hypothesis (paper Sec. 3.3).
  double weight = 1.;           ///< Relative share of the particles (> 0).
  double positionSigma = 0.02;  ///< Standard deviation of the position along the camera X and Y (m).
  double depthSigma = 0.;       ///< Standard deviation along the camera Z (m); <= 0 means positionSigma.
  double rotationSigma = 0.05;  ///< Standard deviation of each theta-u component (rad).
  bool orientationKnown = true; ///< False (position-only): the orientation is any target facing the camera.
};

#endif
