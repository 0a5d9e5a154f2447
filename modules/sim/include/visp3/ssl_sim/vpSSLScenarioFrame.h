/*!
  \file vpSSLScenarioFrame.h
  \brief The true and measured poses of one frame of a simulated scenario.
*/
#ifndef VP_SSL_SCENARIO_FRAME_H
#define VP_SSL_SCENARIO_FRAME_H

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \struct vpSSLScenarioFrame
  \ingroup group_ssl_sim
  \brief One frame of a vpSSLScenario: where the vehicle, its camera and the target are.

  World frame: North-East-Down, the water surface at z = 0. Target frame: the sheet frame of the SSL
  targets (X right, Y down on the printed side, Z into the sheet). Vehicle frame: x forward, y starboard,
  z down.
*/
struct VISP_SSL_EXPORT vpSSLScenarioFrame
{
  unsigned int index = 0;      ///< Frame number, from 0.
  double t = 0.;               ///< Time (s) since the first frame.
  vpHomogeneousMatrix wMv;     ///< True vehicle pose in the world.
  vpHomogeneousMatrix wMc;     ///< True camera pose in the world: wMv vMc.
  vpHomogeneousMatrix wMo;     ///< Target pose in the world.
  vpHomogeneousMatrix cMo;     ///< Ground truth: the target in the camera frame, (wMc)^-1 wMo.
  vpHomogeneousMatrix oMv;     ///< Vehicle odometry (vpSSLDeadReckoning): what the vehicle believes.
  vpHomogeneousMatrix oMvTrue; ///< The true vehicle pose in the odometry frame, what oMv estimates.
  double range = 0.;           ///< Distance from the camera centre to the target origin (m).
};

#endif
