# The libraries hapstab links, found the same way by the build and by find_package(hapstab).
# GMP/MPFR/MPFI and the SDP libraries ship neither CMake nor pkg-config files on Debian,
# so they are found by hand and wrapped as hapstab_dep_<lib> imported targets.
# Each package is REQUIRED in the build. Inside find_package(hapstab) (hapstabConfig.cmake)
# find_dependency marks hapstab NOT FOUND with the missing package's name, and the config stops
# before it imports targets that would name the missing libraries.
include(CMakeFindDependencyMacro)
macro(hapstab_dependency)
  if(CMAKE_FIND_PACKAGE_NAME STREQUAL "hapstab")
    find_dependency(${ARGN})
  else()
    find_package(${ARGN} REQUIRED)
  endif()
endmacro()
hapstab_dependency(Eigen3 3.3 NO_MODULE)
hapstab_dependency(Boost 1.74)
hapstab_dependency(nlohmann_json 3)
hapstab_dependency(tomlplusplus)
hapstab_dependency(Threads)
hapstab_dependency(LAPACK)

function(hapstab_find_c_library var lib header)
  if(TARGET hapstab_dep_${lib})
    return()
  endif()
  find_library(${var}_LIBRARY NAMES ${lib} REQUIRED)
  find_path(${var}_INCLUDE_DIR NAMES ${header} PATH_SUFFIXES ${ARGN} REQUIRED)
  add_library(hapstab_dep_${lib} INTERFACE IMPORTED GLOBAL)
  set_target_properties(hapstab_dep_${lib} PROPERTIES
    INTERFACE_LINK_LIBRARIES "${${var}_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${${var}_INCLUDE_DIR}")
endfunction()
hapstab_find_c_library(GMP gmp gmp.h)
hapstab_find_c_library(MPFR mpfr mpfr.h)
hapstab_find_c_library(MPFI mpfi mpfi.h)
hapstab_find_c_library(DSDP dsdp dsdp5.h dsdp)
hapstab_find_c_library(CSDP sdp declarations.h csdp)

# FLINT (exact polynomial and matrix algebra) and Arb (ball arithmetic). FLINT 3 ships Arb
# inside it (flint/arb.h, one libflint); FLINT 2.9 (Debian 12) has Arb as a separate library
# (libflint-arb, headers arb.h ... in the include root). Both are found here; code includes
# hapstab/numeric/flint.hpp, which picks the right header by HAPSTAB_FLINT3.
if(NOT TARGET hapstab_dep_flint)
  find_library(FLINT_LIBRARY NAMES flint REQUIRED)
  find_path(FLINT_INCLUDE_DIR NAMES flint/fmpq_poly.h REQUIRED)
  add_library(hapstab_dep_flint INTERFACE IMPORTED GLOBAL)
  if(EXISTS "${FLINT_INCLUDE_DIR}/flint/arb.h")
    set_target_properties(hapstab_dep_flint PROPERTIES
      INTERFACE_LINK_LIBRARIES "${FLINT_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${FLINT_INCLUDE_DIR}"
      INTERFACE_COMPILE_DEFINITIONS "HAPSTAB_FLINT3=1")
  else()
    find_library(ARB_LIBRARY NAMES flint-arb arb REQUIRED)
    find_path(ARB_INCLUDE_DIR NAMES arb.h PATH_SUFFIXES arb REQUIRED)
    set_target_properties(hapstab_dep_flint PROPERTIES
      INTERFACE_LINK_LIBRARIES "${ARB_LIBRARY};${FLINT_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${FLINT_INCLUDE_DIR};${ARB_INCLUDE_DIR}"
      INTERFACE_COMPILE_DEFINITIONS "HAPSTAB_FLINT3=0")
  endif()
endif()

# matio (MATLAB .mat files): a dependency of the command only (toolbox/cli/mat_file.cpp), not of
# the library, so find_package(hapstab) does not look for it.
if(NOT CMAKE_FIND_PACKAGE_NAME STREQUAL "hapstab")
  hapstab_find_c_library(MATIO matio matio.h)
  # the command dlopens it by its soname (libmatio.so.11 on Debian 12), not at start-up
  get_filename_component(_matio_real "${MATIO_LIBRARY}" REALPATH)
  file(READ_ELF "${_matio_real}" SONAME HAPSTAB_MATIO_SONAME)
  if(NOT HAPSTAB_MATIO_SONAME)
    get_filename_component(HAPSTAB_MATIO_SONAME "${MATIO_LIBRARY}" NAME)
  endif()
endif()
