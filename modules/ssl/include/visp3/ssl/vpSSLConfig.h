/*!
  \file vpSSLConfig.h
  \brief Version and export macros of the visp-ssl plugin.
*/
#ifndef VP_SSL_CONFIG_H
#define VP_SSL_CONFIG_H

/*!
  \defgroup group_ssl Self-similar landmarks
  Circular self-similar landmarks (SSL) for underwater homing: target model, matching function,
  detector, pose, particle filter and tracker.
*/

//! Version of the plugin, as "major.minor.patch".
#define VISP_SSL_VERSION_STRING "0.1.0"

//! Marks the plugin's public symbols; ViSP's own VISP_EXPORT belongs to ViSP.
#if defined(_WIN32)
#define VISP_SSL_EXPORT __declspec(dllexport)
#else
#define VISP_SSL_EXPORT __attribute__((visibility("default")))
#endif

#endif
