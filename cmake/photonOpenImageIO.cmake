# Finds OpenImageIO and repairs its imported target: Debian's OpenImageIOTargets.cmake lists
# /usr/include/opencv4 among its include directories although OpenCV is only an optional
# dependency, and CMake rejects consumers of a target with a missing include directory.
# Used by photon's own build and by the installed photonConfig.cmake.
if(NOT TARGET OpenImageIO::OpenImageIO)
  include(CMakeFindDependencyMacro)
  find_dependency(OpenImageIO)
endif()
if(TARGET OpenImageIO::OpenImageIO)
  get_target_property(_photon_oiio_dirs OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
  if(_photon_oiio_dirs)
    set(_photon_oiio_kept "")
    foreach(_dir IN LISTS _photon_oiio_dirs)
      if(_dir MATCHES "^\\$<" OR EXISTS "${_dir}")
        list(APPEND _photon_oiio_kept "${_dir}")
      endif()
    endforeach()
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_photon_oiio_kept}")
  endif()
endif()
