# Locates a MeshLab plugin SDK: the headers from MeshLab's source (Debian's `apt-get source`)
# and the binary libmeshlab-common.so of the installed MeshLab. Two API generations:
#
#   2020  MeshLab 2020.09 (Debian bookworm): src/common/interfaces.h, MeshFilterInterface
#         (scripts/setup_meshlab_sdk.sh fetches it into third_party/meshlab-sdk/)
#   2022  MeshLab 2022.02 and later (2025.07 in Debian sid):
#         src/common/plugins/interfaces/filter_plugin.h, FilterPlugin
#         (scripts/setup_sid_root.sh puts it into the sid root's /opt/meshlab-sdk/)
#
# Defines:
#   MESHLAB_PLUGIN_API  "2020" or "2022", from the headers found
#   meshlab::sdk        INTERFACE: <sdk>/src, vcglib, Eigen, MESHLAB_SCALAR (+ MESHLAB_VERSION for
#                       2022): what CMeshO needs; no Qt
#   meshlab::common     IMPORTED libmeshlab-common.so + everything its headers need (Qt5, GLEW)
# (both GLOBAL; they name Qt5::*, Eigen3::Eigen, GLEW::GLEW and OpenGL::GL, which a directory that
# links them must see: include this file from that directory or one above it.)
#
# Cache variables: MESHLAB_SDK_DIR, MESHLAB_LIB_DIR, MESHLAB_PLUGIN_INSTALL_DIR, and for 2022
# MESHLAB_VERSION / MESHLAB_SCALAR (empty: taken from the installed MeshLab, see below).

if(TARGET meshlab::sdk)
  return()
endif()

# --- the source tree ---------------------------------------------------------------------------
set(MESHLAB_SDK_DIR "" CACHE PATH
  "MeshLab source tree: the folder holding src/common/ (scripts/setup_meshlab_sdk.sh prints it for 2020.09, scripts/setup_sid_root.sh uses the sid root's for 2025.07)")
if(NOT MESHLAB_SDK_DIR)
  # Where scripts/setup_meshlab_sdk.sh puts MeshLab 2020.09's source.
  file(GLOB _meshlab_sdk_candidates LIST_DIRECTORIES true
    "${PROJECT_SOURCE_DIR}/third_party/meshlab-sdk/*/src/common/interfaces.h")
  list(SORT _meshlab_sdk_candidates)
  if(_meshlab_sdk_candidates)
    list(GET _meshlab_sdk_candidates 0 _meshlab_interfaces_h)
    get_filename_component(_meshlab_sdk "${_meshlab_interfaces_h}/../../.." ABSOLUTE)
    set(MESHLAB_SDK_DIR "${_meshlab_sdk}" CACHE PATH "MeshLab source tree" FORCE)
    message(STATUS "MeshLab SDK: found ${MESHLAB_SDK_DIR}")
  endif()
endif()
if(EXISTS "${MESHLAB_SDK_DIR}/src/common/plugins/interfaces/filter_plugin.h")
  set(MESHLAB_PLUGIN_API 2022)
elseif(EXISTS "${MESHLAB_SDK_DIR}/src/common/interfaces.h")
  set(MESHLAB_PLUGIN_API 2020)
else()
  message(FATAL_ERROR
    "MESHBRIDGE_BUILD_PLUGIN needs MeshLab's source for the plugin headers.\n"
    "MeshLab 2020.09: run scripts/setup_meshlab_sdk.sh and pass -DMESHLAB_SDK_DIR=<the folder it "
    "prints> (the one holding src/common/interfaces.h and vcglib/).\n"
    "MeshLab 2025.07: run scripts/test_meshlab2025.sh (it builds inside a Debian sid root).\n"
    "Current value: '${MESHLAB_SDK_DIR}'")
endif()
set(MESHLAB_VCGLIB_DIR "${MESHLAB_SDK_DIR}/vcglib")
if(NOT EXISTS "${MESHLAB_VCGLIB_DIR}/vcg/complex/complex.h" AND EXISTS "${MESHLAB_SDK_DIR}/src/vcglib/vcg")
  set(MESHLAB_VCGLIB_DIR "${MESHLAB_SDK_DIR}/src/vcglib")
endif()
if(NOT EXISTS "${MESHLAB_VCGLIB_DIR}/vcg/complex/complex.h")
  message(FATAL_ERROR "No vcglib in ${MESHLAB_SDK_DIR} (looked for vcglib/vcg/complex/complex.h)")
endif()
set(MESHLAB_SDK_VERSION "")
if(EXISTS "${MESHLAB_SDK_DIR}/ML_VERSION")
  file(STRINGS "${MESHLAB_SDK_DIR}/ML_VERSION" MESHLAB_SDK_VERSION LIMIT_COUNT 1)
  string(STRIP "${MESHLAB_SDK_VERSION}" MESHLAB_SDK_VERSION)
endif()
message(STATUS "MeshLab SDK: ${MESHLAB_SDK_DIR} (version ${MESHLAB_SDK_VERSION}, plugin API ${MESHLAB_PLUGIN_API})")

# --- the installed binary ----------------------------------------------------------------------
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

find_package(Eigen3 REQUIRED NO_MODULE)  # 3.4 in bookworm, 5.0 in sid
find_package(GLEW REQUIRED)
find_package(OpenGL REQUIRED)
set(_meshlab_qt_components Core Gui Widgets OpenGL Xml)
if(MESHLAB_PLUGIN_API STREQUAL "2022")
  list(APPEND _meshlab_qt_components Network)
endif()
find_package(Qt5 5.9 REQUIRED COMPONENTS ${_meshlab_qt_components})
set(_meshlab_qt_targets "")
foreach(_c IN LISTS _meshlab_qt_components)
  list(APPEND _meshlab_qt_targets Qt5::${_c})
endforeach()

# --- MESHLAB_VERSION and MESHLAB_SCALAR --------------------------------------------------------
# MeshLab 2020.09: plugins get MESHLAB_SCALAR=float and no version check (Debian adds no define).
# MeshLab >= 2022: PluginManager::checkPlugin() compares the plugin's getMLVersion() -- compiled
# into the plugin from MESHLAB_VERSION and MESHLAB_SCALAR (common/globals.h) -- with its own:
# the precision must match and the first six characters of the version ("2025.0"). Both are
# taken from the installed MeshLab: a probe loads its own libio_base.so and asks it; the version
# is checked against the Debian package's upstream version (dpkg-query) when there is one.
set(MESHLAB_VERSION "" CACHE STRING "MeshLab >= 2022: version the plugin claims (empty: the installed MeshLab's)")
set(MESHLAB_SCALAR "" CACHE STRING "MeshLab >= 2022: float or double (empty: the installed MeshLab's)")
if(MESHLAB_PLUGIN_API STREQUAL "2020")
  set(_meshlab_defines "MESHLAB_SCALAR=float")
else()
  # Probed at every configure (half a second), not cached: a newer MeshLab is picked up.
  set(_meshlab_version "${MESHLAB_VERSION}")
  set(_meshlab_scalar "${MESHLAB_SCALAR}")
  if(NOT _meshlab_version OR NOT _meshlab_scalar)
    set(_probe_plugin "${MESHLAB_LIB_DIR}/plugins/libio_base.so")
    if(NOT EXISTS "${_probe_plugin}")
      message(FATAL_ERROR "No ${_probe_plugin} to read MeshLab's version from: install meshlab, "
        "or set MESHLAB_VERSION and MESHLAB_SCALAR")
    endif()
    try_run(_probe_run _probe_compile
      "${CMAKE_BINARY_DIR}/meshlab_abi_probe"
      "${CMAKE_CURRENT_LIST_DIR}/meshlab_abi_probe.cpp"
      CMAKE_FLAGS "-DINCLUDE_DIRECTORIES=${MESHLAB_SDK_DIR}/src" -DCMAKE_POSITION_INDEPENDENT_CODE=ON
      CXX_STANDARD 17
      # The probe calls nothing in libmeshlab-common.so but must load it (libio_base.so needs it
      # and has no RUNPATH): keep it NEEDED despite Debian's default --as-needed.
      LINK_OPTIONS "LINKER:--no-as-needed"
      LINK_LIBRARIES "${MESHLAB_COMMON_LIBRARY}" Qt5::Core
      COMPILE_OUTPUT_VARIABLE _probe_compile_output
      RUN_OUTPUT_VARIABLE _probe_output
      ARGS "${_probe_plugin}")
    if(NOT _probe_compile OR NOT _probe_run EQUAL 0 OR NOT _probe_output MATCHES "^([^;]+);(float|double)$")
      message(FATAL_ERROR "Could not read MeshLab's version and precision from ${_probe_plugin} "
        "(compiled: ${_probe_compile}, exit: ${_probe_run}): ${_probe_output}\n${_probe_compile_output}\n"
        "Set MESHLAB_VERSION and MESHLAB_SCALAR by hand if you know them.")
    endif()
    if(NOT _meshlab_version)
      set(_meshlab_version "${CMAKE_MATCH_1}")
    endif()
    if(NOT _meshlab_scalar)
      set(_meshlab_scalar "${CMAKE_MATCH_2}")
    endif()
    message(STATUS "MeshLab installed: version ${CMAKE_MATCH_1}, ${CMAKE_MATCH_2} precision (from ${_probe_plugin})")
  endif()
  # Debian's package is only MeshLab's version when the library is Debian's (not a pip-installed
  # pymeshlab's lib/ folder).
  find_program(DPKG_QUERY dpkg-query)
  if(DPKG_QUERY AND MESHLAB_LIB_DIR MATCHES "^/usr/lib/")
    execute_process(COMMAND "${DPKG_QUERY}" -W -f=\${Version} meshlab
      OUTPUT_VARIABLE _deb_version RESULT_VARIABLE _deb_status ERROR_QUIET)
    if(_deb_status EQUAL 0 AND _deb_version MATCHES "^([0-9]+:)?([0-9.]+)")
      set(_deb_upstream "${CMAKE_MATCH_2}")
      string(SUBSTRING "${_deb_upstream}" 0 6 _deb6)
      string(SUBSTRING "${_meshlab_version}" 0 6 _ml6)
      if(NOT _deb6 STREQUAL _ml6)
        message(FATAL_ERROR "MESHLAB_VERSION ${_meshlab_version} does not match the installed "
          "meshlab package ${_deb_version}: MeshLab would refuse the plugin")
      endif()
      message(STATUS "MeshLab package: ${_deb_version}")
    endif()
  endif()
  if(MESHLAB_SDK_VERSION)
    string(SUBSTRING "${MESHLAB_SDK_VERSION}" 0 6 _sdk6)
    string(SUBSTRING "${_meshlab_version}" 0 6 _ml6)
    if(NOT _sdk6 STREQUAL _ml6)
      message(WARNING "MeshLab headers are version ${MESHLAB_SDK_VERSION}, the installed MeshLab "
        "is ${_meshlab_version}: the plugin API may differ")
    endif()
  endif()
  message(STATUS "MeshLab plugin ABI: MESHLAB_VERSION=${_meshlab_version} MESHLAB_SCALAR=${_meshlab_scalar}")
  set(_meshlab_defines "MESHLAB_SCALAR=${_meshlab_scalar};MESHLAB_VERSION=${_meshlab_version}")
endif()

add_library(meshlab::sdk INTERFACE IMPORTED GLOBAL)
# SYSTEM: MeshLab's and vcglib's headers are not ours to warn about.
set_target_properties(meshlab::sdk PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "${MESHLAB_SDK_DIR}/src;${MESHLAB_VCGLIB_DIR}"
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${MESHLAB_SDK_DIR}/src;${MESHLAB_VCGLIB_DIR}"
  # What MeshLab's own build gives every plugin: 2020.09's src/CMakeLists.txt add_definitions
  # (Debian adds no other define), 2022+'s meshlab-common PUBLIC compile definitions.
  INTERFACE_COMPILE_DEFINITIONS "${_meshlab_defines}"
  INTERFACE_LINK_LIBRARIES "Eigen3::Eigen")

add_library(meshlab::common SHARED IMPORTED GLOBAL)
set_target_properties(meshlab::common PROPERTIES
  IMPORTED_LOCATION "${MESHLAB_COMMON_LIBRARY}"
  IMPORTED_SONAME "libmeshlab-common.so"
  INTERFACE_LINK_LIBRARIES "meshlab::sdk;${_meshlab_qt_targets};GLEW::GLEW;OpenGL::GL")
