/*!
  \file vpSSLWaterModel.h
  \brief Underwater image formation (Akkaynak and Treibitz 2018) applied to a rendered target.
*/
#ifndef VP_SSL_WATER_MODEL_H
#define VP_SSL_WATER_MODEL_H

#include <array>
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLWaterModel
  \ingroup group_ssl_sim
  \brief Turns the reflectance and range images of vpSSLRenderer into what an underwater camera sees.

  Per colour channel c in (R, G, B), at a pixel of reflectance \f$ \rho \f$ seen at range \f$ z \f$, the
  revised model of Akkaynak and Treibitz (CVPR 2018, Eq. 2) is
  \f[ I_c = \rho\, E_c\, e^{-\beta^D_c z} + B^\infty_c\, E^B_c \left(1 - e^{-\beta^B_c z}\right) \f]
  with separate coefficients for the direct signal (\f$ \beta^D \f$) and the backscatter
  (\f$ \beta^B \f$). \f$ E_c \f$ is the light on the target: sunlight attenuated down to the working depth
  (\f$ e^{-K_c d} \f$, optionally modulated by caustics) or a lamp at the camera (\f$ P / z^2 \f$, the
  path to the target attenuated like the direct signal). \f$ E^B \f$ is the light that makes the veiling
  light: the same sunlight, or the lamp's power. The direct signal is blurred by forward scattering,
  a Gaussian whose angular width grows linearly with range; rays that miss every object see the water
  column at setBackgroundRange() (infinity: pure veiling light). The sensor then adds
  Poisson-Gaussian noise and quantises to 8 bits.

  Visibility: the presets are named by the range \f$ V \f$ at which a black target's contrast against
  the open water, \f$ e^{-\beta^B_G z} \f$ in this model (Duntley's law), falls to 2 %, i.e.
  \f$ V = \ln 50 / \beta^B_G \approx 3.9 / \beta^B_G \f$ (green, the channel a grey camera sees most).
  See getVisibility().

  \code
  vpSSLRenderer renderer(cam, 640, 480);
  vpImage<float> reflectance, range;
  renderer.render(cMo, reflectance, range);
  vpSSLWaterModel water = vpSSLWaterModel::preset("coastal");
  vpImage<vpRGBa> I;
  water.apply(reflectance, range, cam, 0., 42, I);
  \endcode
*/
class VISP_SSL_EXPORT vpSSLWaterModel
{
public:
  //! Where the light on the target comes from.
  enum vpLightType
  {
    LIGHT_SUN,       ///< Daylight from the surface, attenuated with depth.
    LIGHT_ARTIFICIAL ///< A lamp at the camera, falling off as 1 / range^2.
  };

  //! The "clear" preset.
  vpSSLWaterModel();

  /*!
    A named preset: "clear" (10 m visibility, like the paper's test tank), "coastal" (4 m, the Secchi
    visibility measured at Peel Island), "turbid" (2 m).
    \exception vpException for any other name, listing the valid ones.
  */
  static vpSSLWaterModel preset(const std::string &name);
  //! Names accepted by preset().
  static std::vector<std::string> getPresetNames();

  //! Attenuation of the direct signal, \f$ \beta^D \f$ (1/m) for R, G, B. \exception vpException if negative.
  void setAttenuation(const std::array<double, 3> &betaD);
  /*!
    Backscatter coefficient \f$ \beta^B \f$ (1/m) and veiling light \f$ B^\infty \f$ (relative to a white
    target under the same light) for R, G, B. \exception vpException if negative.
  */
  void setBackscatter(const std::array<double, 3> &betaB, const std::array<double, 3> &veilingLight);
  //! Forward-scatter blur: Gaussian standard deviation in radians per metre of range (capped at 16 px).
  void setForwardScatter(double radPerMetre);
  //! Sunlight: working depth (m), diffuse attenuation K (1/m) for R, G, B, irradiance at the surface.
  void setSunLight(double depth, const std::array<double, 3> &diffuseAttenuation, double surfaceIrradiance = 1.);
  //! A lamp at the camera giving irradiance \e power at 1 m (white light).
  void setArtificialLight(double power);
  /*!
    Caustics (sunlight only): moving bright ripples of relative \e amplitude at the surface, decaying as
    exp(-depth / \e decayDepth), with ripple wavelength \e wavelength (m, on the target) and period
    \e period (s). Drawn in a fronto-parallel approximation (pixel offset x range / focal length).
    amplitude = 0 disables them.
  */
  void setCaustics(double amplitude, double decayDepth = 2., double wavelength = 0.3, double period = 1.5);
  /*!
    Sensor noise, variance \f$ a\,y + b \f$ for a signal \f$ y \f$ in [0, 1] (the normal approximation of
    the Poisson-Gaussian model of Foi et al. 2008: \e a = 1 / full-well electrons, \e b = read noise^2).
    (0, 0) gives a noise-free image.
  */
  void setSensorNoise(double a, double b);
  /*!
    Fixed gain from signal to grey level, 8-bit value = 255 * exposure * I (1: white paper under unit
    light with no water = 255), and auto exposure off. \exception vpException if not > 0.
  */
  void setExposure(double exposure);
  /*!
    Automatic exposure (on by default, mean 0.45): the gain is chosen per frame, within [1/64, 64], so
    that the mean noise-free luminance is \e targetMean (in (0, 1)), as a video camera does.
  */
  void setAutoExposure(bool enable, double targetMean = 0.45);
  //! Range (m) of whatever lies behind the rays that miss the target (default infinity: open water).
  void setBackgroundRange(double range);

  /*!
    Colour image at time \e t (s, for the caustics) from the renderer's reflectance and range images
    (same size), for camera \e cam (its focal length sets the blur and caustic scales). Deterministic
    for a given \e seed.
    \exception vpException if the images are empty or differ in size.
  */
  void apply(const vpImage<float> &reflectance, const vpImage<float> &range, const vpCameraParameters &cam, double t,
             long seed, vpImage<vpRGBa> &I) const;
  //! Grey image: the colour image's luminance (vpImageConvert), as the detector receives it.
  void apply(const vpImage<float> &reflectance, const vpImage<float> &range, const vpCameraParameters &cam, double t,
             long seed, vpImage<unsigned char> &I) const;

  //! Preset name, or "custom" once a setter has changed a parameter.
  const std::string &getName() const { return m_name; }
  //! Range (m) at which a black target's contrast against open water falls to 2 %: ln(50) / beta^B_G.
  double getVisibility() const;
  const std::array<double, 3> &getAttenuation() const { return m_betaD; }    ///< \f$ \beta^D \f$ (1/m).
  const std::array<double, 3> &getBackscatter() const { return m_betaB; }    ///< \f$ \beta^B \f$ (1/m).
  const std::array<double, 3> &getVeilingLight() const { return m_veiling; } ///< \f$ B^\infty \f$.
  vpLightType getLightType() const { return m_light; }                       ///< Light source.
  //! The parameters as a JSON object, for the "water" entry of sequence.json.
  std::string toJson() const;

private:
  void radiance(const vpImage<float> &reflectance, const vpImage<float> &range, const vpCameraParameters &cam, double t,
                std::vector<float> &rgb) const;

  std::string m_name;
  std::array<double, 3> m_betaD;
  std::array<double, 3> m_betaB;
  std::array<double, 3> m_veiling;
  double m_forwardScatter;
  vpLightType m_light;
  double m_depth;
  std::array<double, 3> m_diffuseAttenuation;
  double m_surfaceIrradiance;
  double m_lampPower;
  double m_causticAmplitude;
  double m_causticDecayDepth;
  double m_causticWavelength;
  double m_causticPeriod;
  double m_noiseA;
  double m_noiseB;
  double m_exposure;
  bool m_autoExposure;
  double m_autoExposureMean;
  double m_backgroundRange;
};

#endif
