# Installation and the CMake package:
#   <prefix>/include/osgShadowSilhouette/...              headers (osgShadowSilhouette/CMakeLists.txt)
#   <prefix>/<libdir>/libosgShadowSilhouette.so*          the nodekit (osgShadowSilhouette/CMakeLists.txt)
#   <prefix>/<libdir>/osgPlugins-<OSG version>/osgdb_*.so the OSG plugins (plugins/CMakeLists.txt)
#   <prefix>/<libdir>/cmake/osgShadowSilhouette/          osgShadowSilhouetteConfig.cmake, version, targets
#
# The exported target must not carry this machine's OSG paths: in the build tree it links
# OPENSCENEGRAPH_LIBRARIES and uses OPENSCENEGRAPH_INCLUDE_DIRS (absolute paths); installed,
# it links osgShadowSilhouette::OpenSceneGraph, which the package config builds from the
# consumer's own find_package(OpenSceneGraph).
include(CMakePackageConfigHelpers)

set(OSS_INSTALL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/osgShadowSilhouette)
set(OSS_INSTALL_PLUGIN_DIR ${CMAKE_INSTALL_LIBDIR}/${OSS_OSG_PLUGIN_DIR})
set(OSS_OSG_VERSION_MIN 3.6)
set(OSS_OSG_COMPONENTS "osg osgDB osgUtil osgViewer osgShadow osgGA osgText") # as the nodekit links them

# oss_build_interface_only(<target> <property> <items...>): wraps those items of a target's
# property in $<BUILD_INTERFACE:...>.
function(oss_build_interface_only TARGET PROPERTY)
  get_target_property(_values ${TARGET} ${PROPERTY})
  set(_result)
  foreach(_v IN LISTS _values)
    if(_v IN_LIST ARGN)
      list(APPEND _result "$<BUILD_INTERFACE:${_v}>")
    else()
      list(APPEND _result "${_v}")
    endif()
  endforeach()
  set_property(TARGET ${TARGET} PROPERTY ${PROPERTY} "${_result}")
endfunction()

oss_build_interface_only(osgShadowSilhouette INTERFACE_LINK_LIBRARIES ${OPENSCENEGRAPH_LIBRARIES})
oss_build_interface_only(osgShadowSilhouette INTERFACE_INCLUDE_DIRECTORIES ${OPENSCENEGRAPH_INCLUDE_DIRS})
set_property(TARGET osgShadowSilhouette APPEND PROPERTY
  INTERFACE_LINK_LIBRARIES "$<INSTALL_INTERFACE:osgShadowSilhouette::OpenSceneGraph>")

install(EXPORT osgShadowSilhouetteTargets
  NAMESPACE osgShadowSilhouette::
  FILE osgShadowSilhouetteTargets.cmake
  DESTINATION ${OSS_INSTALL_CMAKE_DIR})

configure_package_config_file(
  ${CMAKE_CURRENT_LIST_DIR}/osgShadowSilhouetteConfig.cmake.in
  ${PROJECT_BINARY_DIR}/osgShadowSilhouetteConfig.cmake
  INSTALL_DESTINATION ${OSS_INSTALL_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_LIBDIR OSS_INSTALL_PLUGIN_DIR)
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/osgShadowSilhouetteConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/osgShadowSilhouetteConfig.cmake
  ${PROJECT_BINARY_DIR}/osgShadowSilhouetteConfigVersion.cmake
  DESTINATION ${OSS_INSTALL_CMAKE_DIR})
