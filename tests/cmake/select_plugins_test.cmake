cmake_minimum_required(VERSION 3.20)
# `cmake -P` test of airshape_select_plugins: a selective build brings in what a plugin
# builds on, before it, and refuses an unknown name.
set(AIRSHAPE_ALL_PLUGINS wing fuselage controlsurfaces structure nacelle rotor generic)
set(AIRSHAPE_PLUGIN_FOLDER ${SOURCE}/plugins)
include(${SOURCE}/cmake/AirshapePlugin.cmake)

airshape_select_plugins(selected controlsurfaces)
if(NOT selected STREQUAL "wing;controlsurfaces")
  message(FATAL_ERROR "controlsurfaces selected '${selected}', expected 'wing;controlsurfaces'")
endif()
airshape_select_plugins(selected structure controlsurfaces nacelle)
if(NOT selected STREQUAL "wing;fuselage;structure;controlsurfaces;nacelle")
  message(FATAL_ERROR "structure, controlsurfaces, nacelle selected '${selected}'")
endif()
message(STATUS "plugin selection: ok")
