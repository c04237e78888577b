# find_package(stereosim): the SDK of the firmware ABI (docs/firmware-abi.md).
#   stereosim::firmware_abi        the C header, include/stereosim/firmware.h
#   stereosim_add_firmware(NAME SOURCES a.c b.c ...)
#                                  a firmware plugin, libNAME.so, exporting only
#                                  its entry stereosim_firmware()
#   stereosim_EXECUTABLE           the installed stereosim, to run it
#   stereosim_REFERENCE_FIRMWARE   the shipped firmware as a plugin
get_filename_component(_stereosim_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
set(stereosim_INCLUDE_DIR "${_stereosim_prefix}/include")
set(stereosim_EXECUTABLE "${_stereosim_prefix}/bin/stereosim")
set(stereosim_REFERENCE_FIRMWARE "${_stereosim_prefix}/lib/stereosim/libstereosim_fw_reference.so")
if(NOT EXISTS "${stereosim_INCLUDE_DIR}/stereosim/firmware.h")
  set(stereosim_FOUND FALSE)
  set(stereosim_NOT_FOUND_MESSAGE "no ${stereosim_INCLUDE_DIR}/stereosim/firmware.h")
  return()
endif()

if(NOT TARGET stereosim::firmware_abi)
  add_library(stereosim::firmware_abi INTERFACE IMPORTED)
  set_target_properties(stereosim::firmware_abi PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${stereosim_INCLUDE_DIR}")
endif()

function(stereosim_add_firmware name)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "stereosim_add_firmware(${name}): give SOURCES")
  endif()
  add_library(${name} MODULE ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE stereosim::firmware_abi)
  # Only the entry is exported (the header marks it); the rest stays the
  # plugin's own, and binds to itself, whatever the host defines.
  set_target_properties(${name} PROPERTIES PREFIX "lib" C_VISIBILITY_PRESET hidden
                                           CXX_VISIBILITY_PRESET hidden
                                           VISIBILITY_INLINES_HIDDEN ON)
  target_link_options(${name} PRIVATE -Wl,-Bsymbolic)
endfunction()
