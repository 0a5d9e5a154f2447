/*!
  \file vpSSLClosedLoop.h
  \brief The closed loop of tutorial-ssl-servo and tutorial-ssl-servo-monte-carlo: the scene (vehicle, target,
  water, behaviour), and one control step (scenario events, rendering, detection, servo input, behaviour update,
  logged row).
*/
#ifndef VP_SSL_CLOSED_LOOP_H
#define VP_SSL_CLOSED_LOOP_H

#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpPoint.h>
#include <visp3/core/vpRect.h>
#include <visp3/core/vpTranslationVector.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLPoseEstimator.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl/vpSSLTracker.h>
#include <visp3/ssl_harness/vpSSLAprilTagBaseline.h>
#include <visp3/ssl_harness/vpSSLAprilTagFusion.h>
#include <visp3/ssl_servo/vpSSLHomingBehaviour.h>
#include <visp3/ssl_servo/vpSSLServoInput.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>
#include <visp3/ssl_sim/vpSSLAuvSimulator.h>
#include <visp3/ssl_sim/vpSSLRenderer.h>
#include <visp3/ssl_sim/vpSSLWaterModel.h>

/*!
  \class vpSSLClosedLoop
  \ingroup group_ssl_harness
  \brief The closed loop of one run: the simulated AUV, the renderer and water model, the detector of the method and the
  homing behaviour, each its own instance (two vpSSLClosedLoop objects share nothing, so they may run in two threads).

  \code
  vpSSLClosedLoop loop(scene, vpSSLClosedLoop::Method::Ssl, cam, 640, 480, 1, seed);
  for (int k = 0; k <= nbSteps; ++k) {
    const vpSSLClosedLoop::Row r = loop.step(k); // events, image, detection, behaviour update
    loop.apply();                         // the command drives the vehicle for one time step
  }
  \endcode
*/
class vpSSLClosedLoop
{
public:
  //! How the target is found at each step. The fused methods run the same particle filter (vpSSLParticleFilter) with
  //! the same odometry and keep servoing on its prediction when the target is lost; the raw ones give the single-frame
  //! pose of each image and nothing when it shows no target.
  enum class Method
  {
    Ssl,         ///< vpSSLTracker (detector, single-frame pose, particle filter with odometry) on the ssl3-a3 sheet.
    AprilTag,    ///< The AprilTag baseline (36h11) on the tag sheet, its corners and pose fed to the same filter;
                 ///< read around where the filter last put the tag, the whole image when that does not give it.
    Truth,       ///< Perfect sensor: the ssl3-a3 landmarks projected at the true pose when in view (no image).
    SslRaw,      ///< vpSSLDetector and vpSSLPoseEstimator alone: the best single-frame pose of each image.
    AprilTagRaw, ///< The AprilTag baseline alone: the tag's corners and pose of each image.
  };

  //! Everything that is fixed for one run: the water, the target, the vehicle's start, the current and the behaviour.
  struct Scene
  {
    std::string water = "clear";  //!< vpSSLWaterModel preset.
    vpHomogeneousMatrix wMoHome;  //!< Target (sheet frame) pose at the start.
    vpHomogeneousMatrix wMvStart; //!< Vehicle pose at the start.
    vpTranslationVector current;  //!< Constant water current (world frame, m/s).
    double standOff = 2.;         //!< Stand-off held in HOME (m).
    double autoDockHold = -1.;    //!< Auto dock after this long at the stand-off (s); < 0: never.
    double autoDockRange = 0.1;   //!< Range tolerance of the auto-dock hold (m), see setAutoDock().
    double autoDockAngle = 5.;    //!< Centring tolerance of the auto-dock hold (deg), see setAutoDock().
    double blindDockRange = 1.3;  //!< See vpSSLHomingBehaviour::setBlindDock().
    double blindDockSpeed = 0.15; //!< See vpSSLHomingBehaviour::setBlindDock().
    //! Give the behaviour the odometry (its SEARCH then holds its ground, vpSSLHomingBehaviour::setSearchHold()).
    bool stationKeeping = false;
    double rangeIntegralGain = 0.; //!< See vpSSLHomingBehaviour::setRangeIntegralGain().
    //! Dock in transit across a current (vpSSLHomingBehaviour::setDockInTransit(), defaults); gives the behaviour
    //! the odometry.
    bool dockInTransit = false;
    double timeStep = 0.2; //!< Control period (s): vision at 5 Hz, dynamics sub-stepped inside.
    std::string scenario;  //!< tutorial-ssl-servo scenario whose events apply (stepEvents()), "" none.
    double duration = 0.;  //!< Scenario duration (s), for the event times.
  };

  //! One logged control step.
  struct Row
  {
    double t;               //!< Time (s).
    double nbPoints;        //!< Measured points of the input (0 when the target is not seen).
    double estRange;        //!< Range the behaviour uses (m).
    double trueRange;       //!< True camera-to-target depth (m; NaN when the target is out of the water).
    double yawDemand;       //!< Yaw rate commanded (rad/s).
    double yawRate;         //!< Yaw rate of the vehicle (rad/s).
    double heading;         //!< Vehicle heading (deg).
    double depth;           //!< Vehicle depth (m).
    double lateral;         //!< Vehicle's offset from the target along the world y axis (m).
    double targetY;         //!< Target's displacement from its start along the world y axis (m).
    double collision;       //!< 1 when the front collision sensor trips, else 0.
    double yRelEst;         //!< Target centre's y (starboard) in the vehicle frame, measured (m).
    double yRelTrue;        //!< The same point's y at the true pose (m).
    vpSSLHomingState state; //!< Behaviour state after the step.
    bool seen;              //!< The behaviour saw the target at this step (vpSSLHomingBehaviour::getTargetSeen()).
  };

  /*!
    The loop of \e method in \e scene with \e cam at \e width x \e height, rendered with \e supersampling,
    its noise and filters seeded with \e seed.
  */
  vpSSLClosedLoop(const Scene &scene, Method method, const vpCameraParameters &cam, unsigned int width,
                  unsigned int height, unsigned int supersampling, long seed);

  vpSSLAuvSimulator &getAuv() { return m_auv; }                  //!< The vehicle.
  vpSSLHomingBehaviour &getHoming() { return m_homing; }         //!< The behaviour.
  const Scene &getScene() const { return m_scene; }              //!< The scene.
  const vpImage<unsigned char> &getImage() const { return m_I; } //!< Last camera image (not with Method::Truth).

  /*!
    Control step \e k (time getAuv().getTime()): the scenario's events, the camera image at the true pose, the
    detection, the behaviour's update. The vehicle does not move: apply() sends the command.
  */
  Row step(int k);

  //! Sends the behaviour's last command to the vehicle: getScene().timeStep seconds of dynamics.
  void apply() { m_homing.apply(m_auv); }

  //! Every method, in the order of methodName()'s names.
  static const std::vector<Method> &allMethods();
  //! "ssl", "apriltag", "truth", "ssl-raw", "apriltag-raw".
  static std::string methodName(Method m);
  //! \e name as a Method; false when it is none of methodName()'s names.
  static bool parseMethod(const std::string &name, Method &m);
  //! Whether \e m shows the AprilTag sheet (rendered instead of ssl3-a3).
  static bool isAprilTag(Method m);
  //! The camera of the paper's vehicle (data/camera/camera-640x480.xml) scaled to \e width x \e height (same field of
  //! view). Reads a file: call it once, before any thread starts.
  static vpCameraParameters scaledCamera(unsigned int width, unsigned int height);
  /*!
    The scenes of tutorial-ssl-servo (paper Sec. 5): fig7, fig8, fig9 (docking), field (coastal, swaying target), all
    from 4.5 m south of the target (camera 3.9 m from it; field 3 m, camera 2.4 m), 0.3 m off its axis, 10 degrees
    off its heading, 0.2 m below it.
  */
  static Scene paperScene(const std::string &scenario, double duration);
  /*!
    Stand-off RMS error (m) over the HOME steps (true range) once settled, i.e. after the range first came within
    0.1 m of the stand-off (the approach from the start is not an error); NaN when no step qualifies. \e n gets the
    number of steps.
  */
  static double standOffRms(const std::vector<Row> &rows, double standOff, size_t &n);
  //! Writes \e rows as the CSV of tutorial-ssl-servo (header included). \exception vpException if it cannot write.
  static void writeRows(const std::string &path, const std::vector<Row> &rows);

private:
  /*!
    The SSL detections without fusion: the best single-frame pose of vpSSLPoseEstimator (small-landmark mode, which
    finds the large landmarks too), as the target's landmarks at that pose; a position-only pose (one or two
    landmarks) gives the landmark it places. \return none() when the image shows no target.
  */
  static vpSSLServoInput singleFrameInput(vpSSLDetector &detector, const vpSSLPoseEstimator &estimator,
                                          const vpCameraParameters &cam, const vpImage<unsigned char> &I);

  //! The tutorial-ssl-servo scenario's events at time \e t: the target taken out and put back, moved, swaying.
  void stepEvents(double t);

  /*!
    The window around the tag where \e fused (the fusion's output of the last image) puts it: its corners' box
    widened by half its size and 48 px on each side. \return false when \e fused places no tag in the image.
  */
  bool tagWindow(const vpSSLServoInput &fused, vpRect &window) const;

  Scene m_scene;
  Method m_method;
  vpCameraParameters m_cam;
  unsigned int m_width, m_height;
  long m_seed;
  vpSSLAuvSimulator m_auv;
  vpSSLHomingBehaviour m_homing;
  vpSSLWaterModel m_water;
  vpSSLRenderer m_renderer;
  vpSSLAprilTagSheet m_sheet;
  vpSSLTarget m_target; // kept alive: the tracker and the truth points refer to its landmarks
  vpSSLTracker m_tracker;
  vpSSLAprilTagBaseline m_tagFinder;
  vpSSLAprilTagFusion m_tagFusion;
  vpRect m_tagWindow;
  bool m_hasTagWindow = false;
  vpSSLDetector m_rawDetector;
  vpSSLPoseEstimator m_rawEstimator;
  vpHomogeneousMatrix m_sMo;
  std::vector<vpPoint> m_truthPoints;
  vpImage<float> m_reflectance, m_range;
  vpImage<unsigned char> m_I;
};

#endif
