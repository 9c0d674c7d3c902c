# The libraries hapstab links, found the same way by the build and by find_package(hapstab).
# GMP/MPFR/MPFI and the SDP libraries ship neither CMake nor pkg-config files on Debian,
# so they are found by hand and wrapped as hapstab_dep_<lib> imported targets.
include(CMakeFindDependencyMacro)
find_dependency(Eigen3 3.3 NO_MODULE)
find_dependency(Boost 1.74)
find_dependency(nlohmann_json 3)
find_dependency(tomlplusplus)
find_dependency(Threads)
find_dependency(LAPACK)

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
