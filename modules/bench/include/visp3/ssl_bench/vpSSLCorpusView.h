/*!
  \file vpSSLCorpusView.h
  \brief One random underwater view of the evaluation corpus and its exact truth.
*/
#ifndef VP_SSL_CORPUS_VIEW_H
#define VP_SSL_CORPUS_VIEW_H

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_bench/vpSSLCorpusPhotos.h>
#include <visp3/ssl_bench/vpSSLCorpusSheet.h>

/*!
  \struct vpSSLCorpusCamera
  \ingroup group_ssl_bench
  \brief Pinhole camera of a corpus view (no distortion), pixel centres at integer coordinates.
*/
struct vpSSLCorpusCamera
{
  std::string name = "vga";  ///< "vga" (640x480), "svga" (800x600) or "wide" (640x480, short focal length).
  unsigned int width = 640;  ///< Image width (px).
  unsigned int height = 480; ///< Image height (px).
  double px = 700.;          ///< Focal length along u (px).
  double py = 700.;          ///< Focal length along v (px).
  double u0 = 319.5;         ///< Principal point u (px).
  double v0 = 239.5;         ///< Principal point v (px).
};

/*!
  \struct vpSSLCorpusFish
  \ingroup group_ssl_bench
  \brief A fish-like occluder: a striped ellipse with a tail, in the water between the camera and the sheet.
*/
struct vpSSLCorpusFish
{
  double u = 0.;                 ///< Body centre (px).
  double v = 0.;                 ///< Body centre (px).
  double length = 40.;           ///< Body length (px), the tail adds 0.35 of it.
  double width = 14.;            ///< Body width (px).
  double angle = 0.;             ///< Body axis from the u axis (rad).
  double stripePeriod = 10.;     ///< Period of the stripes across the body (px).
  double body[3] = {.5, .5, .4}; ///< Body albedo (RGB).
  double stripe = 0.3;           ///< Stripe albedo relative to the body.
  double distance = 1.;          ///< Distance from the camera (m), for the water between.
};

/*!
  \struct vpSSLCorpusPatch
  \ingroup group_ssl_bench
  \brief An occluding rectangle cut from a photograph (a rock, a diver's hand), axis-aligned in the image.
*/
struct vpSSLCorpusPatch
{
  int photo = -1;       ///< Photo index (vpSSLCorpusPhotos), -1: none.
  double u0 = 0.;       ///< Top-left corner (px).
  double v0 = 0.;       ///< Top-left corner (px).
  double u1 = 0.;       ///< Bottom-right corner (px).
  double v1 = 0.;       ///< Bottom-right corner (px).
  double cropX = 0.;    ///< Where in the photo (0..1) the patch is cut.
  double cropY = 0.;    ///< Where in the photo (0..1) the patch is cut.
  double distance = 1.; ///< Distance from the camera (m).
};

/*!
  \struct vpSSLCorpusViewParams
  \ingroup group_ssl_bench
  \brief Everything a corpus view is made of: drawn at random by vpSSLCorpusView::draw(), or set by hand.
*/
struct vpSSLCorpusViewParams
{
  //! Surroundings of the sheet.
  enum Background
  {
    DARK_WATER,   ///< Nothing behind the sheet: the water's own light.
    SAND,         ///< Bright rippled sand in the sheet's plane.
    BOARD,        ///< Planks in the sheet's plane.
    PHOTO,        ///< A photograph in the sheet's plane.
    SECOND_SHEET, ///< Sand with a blank paper sheet partly under the target sheet.
    STRIPES,      ///< Black and white stripes or a chessboard (negatives).
    RINGS         ///< Sand with bull's-eyes of equal-width rings and discs (negatives).
  };
  //! Water type.
  enum Water
  {
    CLEAR,   ///< Visibility 8-15 m.
    COASTAL, ///< Visibility 3-6 m.
    TURBID   ///< Visibility 1-3 m.
  };

  uint64_t seed = 1;                            ///< Seed of the random parts of the rendering (textures, noise).
  bool hasTarget = true;                        ///< False for a negative view (no target sheet).
  vpSSLCorpusCamera camera;                     ///< Camera.
  vpHomogeneousMatrix cMo;                      ///< Pose of the target frame (the sheet's plane) in the camera frame.
  double cropLeft = -1.;                        ///< Sheet rectangle kept (target frame, m).
  double cropTop = -1.;                         ///< Sheet rectangle kept (target frame, m).
  double cropRight = 1.;                        ///< Sheet rectangle kept (target frame, m).
  double cropBottom = 1.;                       ///< Sheet rectangle kept (target frame, m).
  double paper = 0.85;                          ///< Paper albedo.
  double ink = 0.05;                            ///< Ink albedo.
  Background background = SAND;                 ///< Surroundings.
  int photo = -1;                               ///< Photo index of a PHOTO background.
  double textureMetres = 2.;                    ///< Side of the background texture's tile on the plane (m).
  double textureX = 0.;                         ///< Offset of the background texture on the plane (m).
  double textureY = 0.;                         ///< Offset of the background texture on the plane (m).
  double backgroundGain = 1.;                   ///< Albedo scale of the background.
  double sheet2[5] = {0., 0., 0.297, 0.21, 0.}; ///< Second sheet: centre X, Y, width, height (m), angle (rad).
  double sheet2Albedo = 0.8;                    ///< Second sheet's albedo.
  Water water = CLEAR;                          ///< Water type.
  double visibility = 10.;                      ///< Visibility V (m): the green channel's contrast falls to 2 % at V.
  double attenuation[3] = {0.6, 0.39, 0.43};    ///< Attenuation c (1/m), RGB: I = J exp(-c d) + B (1 - exp(-c d)).
  double backscatter[3] = {0.03, 0.22, 0.30};   ///< Water's veiling light B (RGB, in the albedo's units).
  double ambient = 1.;                          ///< Ambient light (daylight from above), uniform.
  double spot = 0.;                             ///< Spotlight strength at 1 m on its axis.
  double spotWidth = 0.5;                       ///< Spotlight's angular width (rad, Gaussian).
  double spotX = 0.;                            ///< Spotlight axis in the camera frame (x/z, y/z).
  double spotY = 0.;                            ///< Spotlight axis in the camera frame (x/z, y/z).
  double vignetting = 0.2;                      ///< Relative light loss at the image corners.
  double gaussSigma = 0.;                       ///< Gaussian blur (defocus and forward scatter), sigma in px.
  double motionLength = 0.;                     ///< Motion blur length (px).
  double motionAngle = 0.;                      ///< Motion blur direction (rad).
  double exposure = 0.8;                        ///< Linear level the image's 99th percentile of luminance is scaled to.
  double noiseGain = 1e-3;                      ///< Shot noise: variance a x of a linear level x.
  double readNoise = 0.005;                     ///< Read noise sigma (linear units).
  double gamma = 2.2;                           ///< Output gamma: value = x^(1/gamma).
  int jpegQuality = 0;                          ///< JPEG quality (0: no compression).
  std::vector<vpSSLCorpusFish> fish;            ///< Fish-like occluders.
  vpSSLCorpusPatch patch;                       ///< Photo patch occluder (photo -1: none).
  int supersampling = 3; ///< Samples per output pixel side on the sheets (area integration of their edges).

  //! Names of the enums, for the CSV files.
  static const char *backgroundName(Background b);
  //! Name of a water type.
  static const char *waterName(Water w);
};

/*!
  \struct vpSSLCorpusLandmarkTruth
  \ingroup group_ssl_bench
  \brief Exact truth of one landmark in a corpus view.
*/
struct vpSSLCorpusLandmarkTruth
{
  std::string name;                ///< Landmark name in the target ("B", "S1", "S2").
  double u = 0.;                   ///< Projection of the circle's centre (px): what the detector must report.
  double v = 0.;                   ///< Projection of the circle's centre (px): what the detector must report.
  double ellipseU = 0.;            ///< Centre of the outer ellipse (px), not the same point under perspective.
  double ellipseV = 0.;            ///< Centre of the outer ellipse (px), not the same point under perspective.
  double a = 0.;                   ///< Semi-axes of the outer ellipse, a >= b (px).
  double b = 0.;                   ///< Semi-axes of the outer ellipse, a >= b (px).
  double theta = 0.;               ///< Major axis angle from the u axis towards +v (rad).
  bool isEllipse = false;          ///< False when the circle is not wholly in front of the camera.
  bool wholeInFrame = false;       ///< The whole outer disc is inside the image.
  bool centreInFrame = false;      ///< The centre is inside the image.
  double viewAngle = 0.;           ///< Angle between the line of sight to the centre and the sheet's normal (deg).
  double range = 0.;               ///< Distance from the camera to the centre (m).
  double rangeOverVisibility = 0.; ///< range / V.
  double blurSigma = 0.;           ///< Total blur sigma (px): Gaussian and motion (length^2 / 12) in quadrature.
  double contrast = 0.;            ///< Grey difference between paper and ink at the landmark, after water and camera.
  double noiseSigma = 0.;          ///< Total grey noise sigma at the landmark's mid-level (shot, read, quantisation).
  double contrastOverNoise = 0.;   ///< contrast / noiseSigma.
  double sheetMargin = 0.;         ///< White paper between the outer ring and the kept sheet's nearest edge, in radii.
  double occludedFraction = 0.;    ///< Fraction of the outer disc's in-frame pixels covered by occluders.
  bool centreOccluded = false;     ///< An occluder covers the centre pixel (never drawn so; checked).
  //! Headline eligibility: whole in frame, radius >= 8 px, centre not occluded, contrast >= 3x noise.
  bool eligible() const { return wholeInFrame && a >= 8. && !centreOccluded && contrastOverNoise >= 3.; }
};

/*!
  \class vpSSLCorpusView
  \ingroup group_ssl_bench
  \brief One view of the corpus: parameters drawn at random for a seed, rendered through a pinhole camera and
  water, with the exact truth of each landmark.

  The image is made as follows, none of it shared with vpSSLRenderer or vpSSLWaterModel:
  - sheet: for every output pixel, s x s samples (s = getSupersampling()) are mapped onto the sheet's plane through
    the exact inverse homography and read from the sheet's mip pyramid (vpSSLCorpusTexture, the level chosen per
    sample from the homography's Jacobian); the cropped sheet's edges and the second sheet are tested analytically
    per sample; the samples are averaged (area integration, as cv::resize INTER_AREA does for an integer factor);
  - surroundings: a texture on the sheet's plane (or the water's own light) read per pixel from its pyramid;
  - light: ambient plus a spotlight (Gaussian cone, inverse square and water loss), vignetting;
  - water: I = J exp(-c d) + B (1 - exp(-c d)) per RGB channel, d the distance along the pixel's ray;
  - occluders: fish and a photo patch in front of the sheet, each with the water between it and the camera;
  - camera: Gaussian blur, motion blur, exposure, Poisson-Gaussian noise, gamma, 8 bits, JPEG (OpenCV), and the
    grey image by ViSP's vpImageConvert::RGBToGrey.
*/
class vpSSLCorpusView
{
public:
  /*!
    Draws the parameters of view \e index of the corpus of seed \e seed (positive views and negatives are drawn
    from separate streams). \e photos decides whether photo backgrounds are possible.
  */
  static vpSSLCorpusViewParams draw(const vpSSLTarget &target, const vpSSLCorpusPhotos &photos, uint64_t seed,
                                    uint64_t index, bool hasTarget);

  /*!
    Exact geometric truth of the landmarks of \e target for the camera and pose of \e p (centre, ellipse, frame,
    angle, range, blur); the photometric fields are filled by render().
  */
  static std::vector<vpSSLCorpusLandmarkTruth> geometry(const vpSSLTarget &target, const vpSSLCorpusViewParams &p);

  /*!
    Homography from the sheet's plane (X, Y, 1) in the target frame to output pixels (u, v, 1) of \e p's camera.
  */
  static cv::Matx33d homography(const vpSSLCorpusViewParams &p);

  //! A view for \e target (its landmarks give the truth).
  explicit vpSSLCorpusView(const vpSSLTarget &target);

  /*!
    Renders \e p. \e sheet is the printed sheet (nullptr, or \e p.hasTarget false: a negative view); an AprilTag
    sheet keeps its tag's white border inside the crop. The truth (getTruth()) is that of the SSL target's
    landmarks whatever the sheet (the same poses in an AprilTag run).
  */
  void render(const vpSSLCorpusViewParams &p, const vpSSLCorpusSheet *sheet, const vpSSLCorpusPhotos &photos);

  const vpImage<unsigned char> &getImage() const { return m_grey; } ///< Grey image (what the detector reads).
  const cv::Mat &getColour() const { return m_colour; }             ///< 8-bit RGB image before the grey conversion.
  const std::vector<vpSSLCorpusLandmarkTruth> &getTruth() const { return m_truth; } ///< Landmarks' truth.
  double getExposureScale() const { return m_exposureScale; } ///< Linear scale the exposure applied.

private:
  vpSSLTarget m_target;
  vpImage<unsigned char> m_grey;
  cv::Mat m_colour;
  std::vector<vpSSLCorpusLandmarkTruth> m_truth;
  double m_exposureScale = 1.;
};

#endif
