/*!
  \file vpSSLBackground.h
  \brief What the camera sees around the target: open water, a seabed, or a photograph on a wall.
*/
#ifndef VP_SSL_BACKGROUND_H
#define VP_SSL_BACKGROUND_H

#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLConfig.h>

class vpSSLRenderer;
class vpSSLScenario;

/*!
  \class vpSSLBackground
  \ingroup group_ssl_sim
  \brief The scene behind a simulated target, as a vpSSLRenderer backdrop placed in a vpSSLScenario's world.

  - \c water: open water all round: rays that miss the target see the veiling light.
  - \c seabed: a procedural seabed (sand ripples, patches, pebbles and rocks; deterministic for a seed) on
    the scenario's sea floor, 1 cm per texel, endless.
  - \c klimt, \c solvay, or any image file: a real photograph (Debian's visp-images-data for the first
    two) on a wall 2 m behind the target's home, 6 m wide, endless, so that the detector meets real clutter.
  A backdrop has a range, so the water model fades it with distance like the target.

  \code
  vpSSLScenario scenario("approach");
  vpSSLBackground background = vpSSLBackground::fromName("seabed", 1);
  background.apply(renderer);                     // the texture
  const vpHomogeneousMatrix wMb = background.getWorldPose(scenario);
  for (const vpSSLScenarioFrame &f : scenario.generate()) {
    renderer.setBackdropPose(f.wMo.inverse() * wMb);
    ...
  }
  \endcode
  See tutorial-ssl-simulate-sequence.cpp.
*/
class VISP_SSL_EXPORT vpSSLBackground
{
public:
  //! Where the backdrop is.
  enum vpBackgroundType
  {
    BACKGROUND_WATER,  ///< No backdrop: open water.
    BACKGROUND_SEABED, ///< A textured sea floor.
    BACKGROUND_WALL    ///< A vertical wall behind the target, facing the camera.
  };

  //! Open water.
  vpSSLBackground();
  /*!
    "water", "seabed" (texture from \e seed), "klimt", "solvay", or the path of an image file (any format
    vpImageIo reads) shown on the wall.
    \exception vpException if the name is none of these and no such image can be read.
  */
  static vpSSLBackground fromName(const std::string &nameOrImage, long seed = 0);
  //! The built-in names.
  static std::vector<std::string> getNames();
  /*!
    A \e size x \e size seabed texture (reflectance 255 = white paper), deterministic for \e seed: sand with
    ripples and patches of fine detritus, pebbles and a few rocks, mean reflectance about 0.3.
    \exception vpException if size < 16.
  */
  static vpImage<unsigned char> seabedTexture(unsigned int size, long seed);

  //! Sets the renderer's backdrop texture (or removes it for open water).
  void apply(vpSSLRenderer &renderer) const;
  //! Pose wMb of the backdrop frame in the scenario's world (meaningless for open water).
  vpHomogeneousMatrix getWorldPose(const vpSSLScenario &scenario) const;

  const std::string &getName() const { return m_name; }                  ///< Name or image path.
  vpBackgroundType getType() const { return m_type; }                    ///< Kind of backdrop.
  const vpImage<unsigned char> &getTexture() const { return m_texture; } ///< Texture (empty for water).
  double getTexelSize() const { return m_texelSize; }                    ///< Metres per texel.

private:
  std::string m_name;
  vpBackgroundType m_type;
  vpImage<unsigned char> m_texture;
  double m_texelSize;
};

#endif
