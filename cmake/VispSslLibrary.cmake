# visp_ssl_add_library(NAME): the plugin's usual library from the calling folder: every src/*.cpp and
# include/visp3/<NAME without visp_>/*.h, the project's version, the include folder for the build and install
# trees, the warnings, installed into the VISP_SSLTargets export set with its headers. Links are the caller's.
function(visp_ssl_add_library name)
  # ViSP's convention (visp_detection -> visp3/detection/): the header folder says which library to link.
  string(REGEX REPLACE "^visp_" "" folder ${name})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  file(GLOB headers CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/include/visp3/${folder}/*.h)
  add_library(${name} ${sources} ${headers})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${name} VERSION ${PROJECT_VERSION}
                                           SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                            $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_options(${name} PRIVATE -Wall -Wextra)
  install(TARGETS ${name} EXPORT VISP_SSLTargets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/visp3/${folder})
endfunction()
