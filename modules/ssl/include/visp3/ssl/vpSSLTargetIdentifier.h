/*!
  \file vpSSLTargetIdentifier.h
  \brief Decides which detected landmarks are the target's (paper Sec. 3.2, cases 1-3).
*/
#ifndef VP_SSL_TARGET_IDENTIFIER_H
#define VP_SSL_TARGET_IDENTIFIER_H

#include <vector>

#include <visp3/ssl/vpSSLLandmark.h>
#include <visp3/ssl/vpSSLTarget.h>

/*!
  \struct vpSSLTargetMatch
  \ingroup group_ssl
  \brief The target as identified in one image.
*/
struct VISP_SSL_EXPORT vpSSLTargetMatch
{
  bool found = false;         ///< True when at least one of the target's landmarks was identified.
  unsigned int nbMatched = 0; ///< How many of the target's landmarks were matched (the paper's nbPoints).
  std::vector<int> detection; ///< For each target landmark, the index of its detection, or -1.
  double residual = 0.;       ///< Mean geometric residual of the match (relative to the big radius).
};

/*!
  \class vpSSLTargetIdentifier
  \ingroup group_ssl
  \brief Labels detected landmarks with the target's landmarks using only what the model knows.

  Each landmark's outer ellipse tells how the target plane is tilted there: undoing it (an affine
  rectification) brings the landmarks' relative positions back to the printed ones up to a rotation
  and a scale, and keeps the orientation of the plane, so that a mirrored target (a reflection in the
  water surface, paper Sec. 3.1) is told apart by the handedness of its triangle. A hypothesis pairs
  two detections with two target landmarks whose radius ratio and distance agree; it predicts where
  the other landmarks must be and of what size, and the hypothesis that explains most detections
  with the smallest residual wins.

  As in the paper, when fewer than three landmarks are identified, a lone landmark is taken for the
  big one (case 1) and two landmarks that cannot be told apart count as the big one alone (case 2).
  Landmarks that match each other but not the big one (S1 and S2 of ssl3-a3 without B) keep their own
  labels, so that their radii give the right range (Eq. 6); the big one's entry is then -1. Two such
  landmarks of equal size swap under a half turn of the target, which no image of them alone can tell:
  they are labelled as if the target were the right way up in the image (the least rotation), and a
  tracker that knows the orientation relabels them by its prediction.

  Threads: identify() is const and safe to call from several threads on one object (its buffers are per
  thread); the setters are not.

  \code
  vpSSLTargetIdentifier identifier(vpSSLTarget::ssl3a3());
  vpSSLTargetMatch match = identifier.identify(landmarks);
  if (match.found && match.detection[0] >= 0) { ... landmarks[match.detection[0]] is B ... }
  // match.found with match.detection[0] == -1: only S1 and S2 were identified.
  \endcode
*/
class VISP_SSL_EXPORT vpSSLTargetIdentifier
{
public:
  //! Identifier for \e target.
  explicit vpSSLTargetIdentifier(const vpSSLTarget &target = vpSSLTarget::ssl3a3());

  //! Relative tolerance on radius ratios (default 0.35).
  void setRadiusTolerance(double tol) { m_radiusTol = tol; }
  //! Relative tolerance on rectified centre distances (default 0.25).
  void setDistanceTolerance(double tol) { m_distanceTol = tol; }
  //! The target model.
  const vpSSLTarget &getTarget() const { return m_target; }

  //! Identifies the target among \e landmarks.
  vpSSLTargetMatch identify(const std::vector<vpSSLLandmark> &landmarks) const;
  //! Same, into \e result, without allocating once its buffers have grown (per-frame use).
  void identify(const std::vector<vpSSLLandmark> &landmarks, vpSSLTargetMatch &result) const;

private:
  vpSSLTarget m_target;
  double m_radiusTol;
  double m_distanceTol;
  int m_big; // index of the biggest target landmark
};

#endif
