/*!
  \file vpSSLRenderer.h
  \brief Exact, anti-aliased rendering of planar targets at a known pose.
*/
#ifndef VP_SSL_RENDERER_H
#define VP_SSL_RENDERER_H

#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/core/vpPlane.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>

/*!
  \class vpSSLRenderer
  \ingroup group_ssl_sim
  \brief Ray-casts a printed planar target into a camera view at a ground-truth pose.

  Each pixel is split into n x n sub-pixels; each sub-pixel's ray (through the camera model,
  distortion included) is intersected with the target plane Z = 0 of the target frame and the
  printed pattern is evaluated there exactly (vpSSLPattern). The pixel value is the mean of its
  sub-pixels, so edges are anti-aliased and the geometry is exact to the sampling.

  Intensities are reflectances in [0, 1] of the printed sheet: black ink, white paper, and a
  background value for rays that miss the sheet (or a background image).

  Distortion: rays are cast with ViSP's pixel-to-meter model (vpPixelMeterConversion: kdu, or
  Kannala-Brandt), so that a detector undistorting with the same camera recovers the exact rays;
  projectLandmarks() uses the meter-to-pixel model (kud). ViSP's kud and kdu are only approximate
  inverses of each other: for a consistent pair, fit kdu to kud (the tests' sslt::cameraWithDistortion
  leaves 0.23 px in the corners of a 640 x 480 image at kud = -0.05, 0.03 px within 200 px of the centre).

  Scene around the sheet (optional, see tutorial-ssl-simulate-sequence.cpp):
  - setAprilTagSheet() prints an AprilTag 36h11 sheet instead of the SSL target, for the baseline.
  - setBackdrop() adds a textured plane (a seabed, a wall with a photograph) seen where rays miss the
    sheet; its range goes to the range image, so the water model fades it with distance.
  - setWaterSurface() adds the water-air interface: a ray that reaches it from below is reflected with the
    Fresnel reflectance of water to air, total beyond the critical angle of 48.6 degrees from the normal
    (paper Sec. 3.1: the target's mirror image, of opposite handedness), and otherwise also sees the
    bright sky through Snell's window. The range of a reflected ray is its whole path in the water.
  - setMaxRange() stops the rays where the water has left nothing of the signal.

  Rows are rendered in parallel (OpenMP); a 640 x 480 frame at 16 samples per pixel costs about
  60 ms on one core when the target fills it, far less when it is small.

  \code
  vpCameraParameters cam(600, 600, 320, 240);
  vpSSLRenderer renderer(cam, 640, 480);
  renderer.setTarget(vpSSLTarget::ssl3a3());
  vpImage<unsigned char> I;
  renderer.render(vpHomogeneousMatrix(0, 0, 2, 0, 0, 0), I);
  \endcode
*/
class VISP_SSL_EXPORT vpSSLRenderer
{
public:
  //! Renderer for images of \e width x \e height pixels seen through \e cam; the target is ssl3-a3 until setTarget().
  vpSSLRenderer(const vpCameraParameters &cam, unsigned int width, unsigned int height);

  /*!
    The SSL target to print on the sheet (its sheet rectangle and landmarks).
    \exception vpException if the sheet has no area or a landmark is off the plane Z = 0.
  */
  void setTarget(const vpSSLTarget &target);
  //! Number of sub-pixels per axis (default 4, i.e. 16 samples per pixel). \exception vpException if not in [1, 64].
  void setSupersampling(unsigned int n);
  /*!
    Reflectances in [0, 1] of the ink, the paper, and the background outside the sheet (defaults 0, 1
    and 0.5). The back of the sheet, seen from behind, is blank paper.
    \exception vpException if one is outside [0, 1].
  */
  void setReflectances(double black, double white, double background);
  /*!
    Image seen where rays miss the sheet (e.g. a cluttered scene, for false-positive tests), read as
    reflectance I / 255 at the pixel being rendered; an empty image restores the uniform background.
    \exception vpException if its size is not the renderer's.
  */
  void setBackgroundImage(const vpImage<unsigned char> &I);
  /*!
    Prints \e sheet instead of the SSL target. render() and isTargetInView() then take cMo as the pose of
    the tag frame (vpSSLAprilTagSheet: the frame of vpDetectorAprilTag::getPose()), and projectLandmarks()
    returns the four corners of the black square in the order of vpDetectorAprilTag::getPolygon().
    setTarget() switches back to an SSL target.
  */
  void setAprilTagSheet(const vpSSLAprilTagSheet &sheet);
  /*!
    A textured plane behind the scene: the plane Z = 0 of a frame b whose pose in the target frame is set by
    setBackdropPose(), showing \e texture (reflectance I / 255) with its centre at b's origin, columns along
    X and rows along Y, \e texelSize metres per texel, repeated by mirroring so that it has no end and no seam.
    An empty texture removes the backdrop.
    \exception vpException if texelSize is not > 0.
  */
  void setBackdrop(const vpImage<unsigned char> &texture, double texelSize);
  //! Pose oMb of the backdrop frame in the target frame (the frame of cMo); identity until set.
  void setBackdropPose(const vpHomogeneousMatrix &oMb);
  /*!
    The water surface, as a plane in the target frame (the frame of cMo) whose normal (A, B, C) points up,
    into the air. The camera must be below it.
    \exception vpException if the normal is zero.
  */
  void setWaterSurface(const vpPlane &surface);
  //! Removes the water surface.
  void clearWaterSurface();
  /*!
    Range (m, along the ray, reflections included) beyond which nothing is drawn: the ray is a miss, with an
    infinite range. Default: infinity. Water that leaves less than half a grey level of the direct signal at
    some range (vpSSLWaterModel) makes everything farther pure veiling light: cutting the rays there gives
    the same image, and spares the texture lookups and the water model's blur of a seabed reaching the horizon.
    \exception vpException if not > 0.
  */
  void setMaxRange(double range);
  //! See setMaxRange().
  double getMaxRange() const { return m_maxRange; }

  //! The SSL target printed on the sheet.
  const vpSSLTarget &getTarget() const { return m_target; }
  //! Number of sub-pixels per axis.
  unsigned int getSupersampling() const { return m_supersampling; }
  //! True after setAprilTagSheet(), until setTarget().
  bool hasAprilTagSheet() const { return m_aprilTag; }
  //! The AprilTag sheet (meaningful when hasAprilTagSheet()).
  const vpSSLAprilTagSheet &getAprilTagSheet() const { return m_tagSheet; }
  //! True when a backdrop texture is set.
  bool hasBackdrop() const { return !m_backdrop.empty(); }
  //! True when a water surface is set.
  bool hasWaterSurface() const { return m_hasSurface; }

  //! Renders the target at pose cMo (target frame in the camera frame) as an 8-bit image (255 * reflectance).
  void render(const vpHomogeneousMatrix &cMo, vpImage<unsigned char> &I) const;
  //! Renders reflectance in [0, 1] and the range (m) along each pixel's central ray (infinity where it misses the
  //! sheet).
  void render(const vpHomogeneousMatrix &cMo, vpImage<float> &reflectance, vpImage<float> &range) const;

  //! Projection of the landmark centres at cMo, in pixels (distortion included), in target order; a centre
  //! behind the camera (Z <= 0) gets NaN coordinates. For an AprilTag sheet, its four corners.
  std::vector<vpImagePoint> projectLandmarks(const vpHomogeneousMatrix &cMo) const;
  /*!
    Whether some of the printed side of the sheet is in the image at cMo: a 17 x 13 grid of points over the
    sheet is projected, and one inside the image and in front of the camera, seen from the printed side,
    is enough. The target may still be hidden behind the water surface's reflection of something else.
  */
  bool isTargetInView(const vpHomogeneousMatrix &cMo) const;

  const vpCameraParameters &getCameraParameters() const { return m_cam; } ///< Camera model.
  unsigned int getWidth() const { return m_width; }                       ///< Image width.
  unsigned int getHeight() const { return m_height; }                     ///< Image height.

private:
  struct Disc
  {
    double x, y, radius, radius2, p;
    std::vector<double> ringRadius2; //!< Squared outer radius of ring k at [k] (ring 0, outermost, is black).
  };
  struct Scene;
  void renderCore(const vpHomogeneousMatrix &cMo, float *reflectance, float *range, unsigned char *grey) const;
  struct OpenWater;
  void openWater(const Scene &scene, OpenWater &open) const;
  double shadePixel(const Scene &scene, unsigned int u, unsigned int v, double background, bool separable,
                    const std::vector<double> &colProducts, const std::vector<double> &rowProducts) const;
  static float rangeOf(double x, double y, double t);
  float centralRange(const Scene &scene, unsigned int u, unsigned int v, double background) const;
  Scene makeScene(const vpHomogeneousMatrix &cMo) const;
  double shade(const Scene &scene, const double p[3], const double d[3], double background, bool surface, double path0,
               double &t) const;
  double sheetValue(double X, double Y) const;
  double backdropValue(double a, double b, double footprint) const;
  vpHomogeneousMatrix sheetPose() const;
  void updateRayCache();
  void normalisedRay(unsigned int u, unsigned int v, unsigned int i, unsigned int j, double &x, double &y) const;

  vpCameraParameters m_cam;
  unsigned int m_width;
  unsigned int m_height;
  unsigned int m_supersampling;
  vpSSLTarget m_target;
  double m_black;
  double m_white;
  double m_background;
  vpImage<unsigned char> m_backgroundImage;
  std::vector<Disc> m_discs;
  bool m_aprilTag;
  vpSSLAprilTagSheet m_tagSheet;
  //! Backdrop texture and its box-filtered pyramid (level k has 2^k texels per texel of level 0), so that a
  //! distant backdrop is sampled at its footprint: no aliasing, and few cache misses.
  std::vector<vpImage<unsigned char>> m_backdrop;
  double m_texelSize;
  vpHomogeneousMatrix m_oMb;
  bool m_hasSurface;
  vpPlane m_surface;
  double m_maxRange;
  //! Undistorted normalised coordinates spanned by the image border, so that isTargetInView() does not take
  //! a point far outside the field of view, folded back by a distortion polynomial, for a visible one.
  double m_fovMinX, m_fovMaxX, m_fovMinY, m_fovMaxY;
  //! Undistorted normalised x of every sub-pixel column, (u + offset - u0) / px; m_subY likewise for rows.
  //! The perspective models are separable up to the kdu factor, so two small tables cover all rays.
  std::vector<double> m_subX;
  std::vector<double> m_subY;
  double m_kdu; //!< kdu of the perspective model with distortion, 0 otherwise.
  //! Normalised (x, y) of every sub-pixel ray, kept only for the Kannala-Brandt model, whose
  //! pixel-to-meter conversion is an iterative inversion.
  std::vector<float> m_rayCache;
  std::vector<float> m_centralRayCache; //!< Same, at the pixel centres (for the range image).
};

#endif
