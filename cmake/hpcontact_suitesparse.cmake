# CHOLMOD and UMFPACK (SuiteSparse, used through Eigen's CholmodSupport and UmfPackSupport) as
# one imported target, hpcontact::suitesparse. Included by the build and by the installed
# package configuration, so that the exported targets name no absolute library path of the
# machine they were built on. Sets HPC_SUITESPARSE_FOUND.
if(TARGET hpcontact::suitesparse)
  set(HPC_SUITESPARSE_FOUND TRUE)
  return()
endif()
find_path(HPC_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(HPC_CHOLMOD_LIBRARY cholmod)
find_library(HPC_UMFPACK_LIBRARY umfpack)
find_library(HPC_SUITESPARSECONFIG_LIBRARY suitesparseconfig)  # its allocator, which a test replaces
if(HPC_CHOLMOD_INCLUDE_DIR AND HPC_CHOLMOD_LIBRARY AND HPC_UMFPACK_LIBRARY AND HPC_SUITESPARSECONFIG_LIBRARY)
  set(HPC_SUITESPARSE_FOUND TRUE)
  add_library(hpcontact::suitesparse INTERFACE IMPORTED)
  set_target_properties(hpcontact::suitesparse PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${HPC_CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${HPC_CHOLMOD_LIBRARY};${HPC_UMFPACK_LIBRARY};${HPC_SUITESPARSECONFIG_LIBRARY}")
else()
  set(HPC_SUITESPARSE_FOUND FALSE)
endif()
