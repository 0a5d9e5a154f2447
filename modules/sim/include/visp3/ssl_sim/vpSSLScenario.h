/*!
  \file vpSSLScenario.h
  \brief Vehicle and target trajectories of the simulated sequences, with ground truth and odometry.
*/
#ifndef VP_SSL_SCENARIO_H
#define VP_SSL_SCENARIO_H

#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpPlane.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl_sim/vpSSLDeadReckoning.h>
#include <visp3/ssl_sim/vpSSLScenarioFrame.h>

/*!
  \class vpSSLScenario
  \ingroup group_ssl_sim
  \brief A named trajectory of an AUV with a forward-looking camera around a target: the true poses of every
  frame, the camera-to-target ground truth cMo and the vehicle's odometry oMv with realistic drift.

  The world is North-East-Down with the water surface at z = 0. The target stands upright facing south,
  its origin 2.5 m deep above a seabed at 4 m (the paper's field trials: about 3 m of water, the target
  floating mid-water); the camera looks at it from the south. Scenarios (getNames(), getDescription()):
  - \c approach: straight approach from 10 m to 0.5 m, with a slight weave and attitude wobble;
  - \c orbit: an arc from 60 degrees left to 60 degrees right of the target's axis at a constant 3 m;
  - \c spiral: a descending spiral: from 1.2 m above the target down to its level, circling its axis
    (1.5 turns, radius 1.0 to 0.2 m) while closing from 8 m to 1.5 m;
  - \c leave-return: at 4 to 3 m, the vehicle turns 80 degrees away (the target leaves the view) and back;
  - \c left-right: paper Fig. 8: the vehicle holds 2 m while the target is moved 0.8 m left, then right,
    then back, turning by up to 20 degrees; the vehicle yaws to follow it, a little late;
  - \c reflection: paper Sec. 3.1: a target 0.45 m below a calm surface approached from 6 m to 1.5 m
    from slightly below it, so that its mirror image in the surface (opposite handedness) is in view too.
  Set the water surface in the renderer with surfaceInTarget() to see the reflection.

  The path does not depend on the number of frames: setFrames() only samples it (and sets the speed).
  The odometry (vpSSLDeadReckoning) is deterministic for setSeed().

  \code
  vpSSLScenario scenario("approach");
  scenario.setFrames(100, 10.);
  scenario.setSeed(1);
  for (const vpSSLScenarioFrame &f : scenario.generate()) {
    renderer.render(f.cMo, reflectance, range);
    ...
  }
  \endcode
  See tutorial-ssl-simulate-sequence.cpp.
*/
class VISP_SSL_EXPORT vpSSLScenario
{
public:
  //! The "approach" scenario.
  vpSSLScenario();
  //! Scenario \e name. \exception vpException for an unknown name, listing the valid ones.
  explicit vpSSLScenario(const std::string &name);

  //! Names of the scenarios.
  static std::vector<std::string> getNames();
  //! One-line description of scenario \e name. \exception vpException for an unknown name.
  static std::string getDescription(const std::string &name);
  //! The forward-looking camera of a small AUV: at its nose (0.5 m ahead), optical axis along its x axis.
  static vpHomogeneousMatrix getDefaultCameraToVehicle();
  /*!
    The water surface (world z = 0) as a plane in the frame of a target at \e wMo, its normal pointing into
    the air, for vpSSLRenderer::setWaterSurface().
  */
  static vpPlane surfaceInTarget(const vpHomogeneousMatrix &wMo);

  //! \e n frames at \e fps frames per second (default 100 at 10). \exception vpException if n = 0 or fps <= 0.
  void setFrames(unsigned int n, double fps);
  /*!
    Ranges (m) from the camera to the target origin at the first and last frames, replacing the scenario's
    (approach 10 to 0.5, orbit 3 to 3, spiral 8 to 1.5, leave-return 4 to 3, left-right 2 to 2,
    reflection 6 to 1.5). \exception vpException if one is not > 0.3 m.
  */
  void setRanges(double startRange, double endRange);
  //! Seed of the odometry noise (default 0).
  void setSeed(long seed) { m_seed = seed; }
  //! Camera pose in the vehicle frame (default getDefaultCameraToVehicle()).
  void setCameraToVehicle(const vpHomogeneousMatrix &vMc) { m_vMc = vMc; }
  //! The odometry model, with its noise figures.
  void setOdometry(const vpSSLDeadReckoning &odometry) { m_odometry = odometry; }

  const std::string &getName() const { return m_name; }                   ///< Scenario name.
  unsigned int getNbFrames() const { return m_nbFrames; }                 ///< Number of frames.
  double getFps() const { return m_fps; }                                 ///< Frames per second.
  double getStartRange() const { return m_startRange; }                   ///< Range at the first frame (m).
  double getEndRange() const { return m_endRange; }                       ///< Range at the last frame (m).
  long getSeed() const { return m_seed; }                                 ///< Odometry seed.
  const vpHomogeneousMatrix &getCameraToVehicle() const { return m_vMc; } ///< vMc.
  //! Target pose in the world when it is not moved.
  vpHomogeneousMatrix getTargetHome() const;
  //! Depth of the seabed (m).
  double getSeabedDepth() const { return m_seabedDepth; }

  //! The poses of every frame.
  std::vector<vpSSLScenarioFrame> generate() const;

private:
  void poses(double s, vpHomogeneousMatrix &wMc, vpHomogeneousMatrix &wMo) const;

  std::string m_name;
  unsigned int m_nbFrames;
  double m_fps;
  double m_startRange;
  double m_endRange;
  double m_targetDepth;
  double m_seabedDepth;
  long m_seed;
  vpHomogeneousMatrix m_vMc;
  vpSSLDeadReckoning m_odometry;
};

#endif
