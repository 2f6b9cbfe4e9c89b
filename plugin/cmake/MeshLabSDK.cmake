# Locates MeshLab 2020.09's plugin SDK: the headers from its source (`apt-get source meshlab`, see
# scripts/setup_meshlab_sdk.sh) and Debian's binary libmeshlab-common.so. Defines:
#
#   meshlab::sdk     INTERFACE: <sdk>/src, <sdk>/vcglib, Eigen, MESHLAB_SCALAR=float (what CMeshO
#                    needs; no Qt)
#   meshlab::common  IMPORTED libmeshlab-common.so + everything its headers need (Qt5, GLEW)
#
# Cache variables: MESHLAB_SDK_DIR, MESHLAB_LIB_DIR, MESHLAB_PLUGIN_INSTALL_DIR.

if(TARGET meshlab::sdk)
  return()
endif()

# --- the source tree ---------------------------------------------------------------------------
set(MESHLAB_SDK_DIR "" CACHE PATH
  "MeshLab 2020.09 source tree: the folder holding src/common/interfaces.h and vcglib/ (scripts/setup_meshlab_sdk.sh prints it)")
if(NOT MESHLAB_SDK_DIR)
  # Where scripts/setup_meshlab_sdk.sh puts it.
  file(GLOB _meshlab_sdk_candidates LIST_DIRECTORIES true
    "${PROJECT_SOURCE_DIR}/third_party/meshlab-sdk/*/src/common/interfaces.h")
  list(SORT _meshlab_sdk_candidates)
  if(_meshlab_sdk_candidates)
    list(GET _meshlab_sdk_candidates 0 _meshlab_interfaces_h)
    get_filename_component(_meshlab_sdk "${_meshlab_interfaces_h}/../../.." ABSOLUTE)
    set(MESHLAB_SDK_DIR "${_meshlab_sdk}" CACHE PATH "MeshLab 2020.09 source tree" FORCE)
    message(STATUS "MeshLab SDK: found ${MESHLAB_SDK_DIR}")
  endif()
endif()
if(NOT EXISTS "${MESHLAB_SDK_DIR}/src/common/interfaces.h")
  message(FATAL_ERROR
    "MESHBRIDGE_BUILD_PLUGIN needs MeshLab 2020.09's source for the plugin headers.\n"
    "Run scripts/setup_meshlab_sdk.sh and pass -DMESHLAB_SDK_DIR=<the folder it prints> "
    "(the one holding src/common/interfaces.h and vcglib/). Current value: '${MESHLAB_SDK_DIR}'")
endif()
set(MESHLAB_VCGLIB_DIR "${MESHLAB_SDK_DIR}/vcglib")
if(NOT EXISTS "${MESHLAB_VCGLIB_DIR}/vcg/complex/complex.h" AND EXISTS "${MESHLAB_SDK_DIR}/src/vcglib/vcg")
  set(MESHLAB_VCGLIB_DIR "${MESHLAB_SDK_DIR}/src/vcglib")
endif()
if(NOT EXISTS "${MESHLAB_VCGLIB_DIR}/vcg/complex/complex.h")
  message(FATAL_ERROR "No vcglib in ${MESHLAB_SDK_DIR} (looked for vcglib/vcg/complex/complex.h)")
endif()
if(EXISTS "${MESHLAB_SDK_DIR}/ML_VERSION")
  file(STRINGS "${MESHLAB_SDK_DIR}/ML_VERSION" MESHLAB_SDK_VERSION LIMIT_COUNT 1)
  if(NOT MESHLAB_SDK_VERSION MATCHES "^2020\\.")
    message(WARNING "MeshLab SDK version ${MESHLAB_SDK_VERSION}: this plugin is written for the 2020.09 API")
  endif()
endif()

# --- Debian's binary ---------------------------------------------------------------------------
set(MESHLAB_LIB_DIR "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/meshlab" CACHE PATH
  "Folder of MeshLab's libmeshlab-common.so (Debian: /usr/lib/<multiarch>/meshlab)")
if(NOT CMAKE_LIBRARY_ARCHITECTURE AND NOT EXISTS "${MESHLAB_LIB_DIR}")
  set(MESHLAB_LIB_DIR "/usr/lib/x86_64-linux-gnu/meshlab" CACHE PATH "" FORCE)
endif()
set(MESHLAB_PLUGIN_INSTALL_DIR "${MESHLAB_LIB_DIR}/plugins" CACHE PATH
  "Where `cmake --install` puts the plugin (MeshLab's plugins folder)")
find_library(MESHLAB_COMMON_LIBRARY NAMES meshlab-common PATHS "${MESHLAB_LIB_DIR}" NO_DEFAULT_PATH)
if(NOT MESHLAB_COMMON_LIBRARY)
  message(FATAL_ERROR "libmeshlab-common.so not found in ${MESHLAB_LIB_DIR}: install Debian's "
    "meshlab package (scripts/setup_meshlab_sdk.sh does) or set MESHLAB_LIB_DIR")
endif()

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(GLEW REQUIRED)
find_package(OpenGL REQUIRED)
find_package(Qt5 5.9 REQUIRED COMPONENTS Core Gui Widgets OpenGL Xml)

add_library(meshlab::sdk INTERFACE IMPORTED)
# SYSTEM: MeshLab's and vcglib's headers are not ours to warn about.
set_target_properties(meshlab::sdk PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "${MESHLAB_SDK_DIR}/src;${MESHLAB_VCGLIB_DIR}"
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${MESHLAB_SDK_DIR}/src;${MESHLAB_VCGLIB_DIR}"
  # What MeshLab 2020.09's src/CMakeLists.txt gives every plugin (add_definitions); Debian adds
  # no other define. MESHLAB_VERSION is only defined for libmeshlab-common itself.
  INTERFACE_COMPILE_DEFINITIONS "MESHLAB_SCALAR=float"
  INTERFACE_LINK_LIBRARIES "Eigen3::Eigen")

add_library(meshlab::common SHARED IMPORTED)
set_target_properties(meshlab::common PROPERTIES
  IMPORTED_LOCATION "${MESHLAB_COMMON_LIBRARY}"
  IMPORTED_SONAME "libmeshlab-common.so"
  INTERFACE_LINK_LIBRARIES
    "meshlab::sdk;Qt5::Core;Qt5::Gui;Qt5::Widgets;Qt5::OpenGL;Qt5::Xml;GLEW::GLEW;OpenGL::GL")
