# airshape_add_plugin(NAME source...): a plugin module named libairshape_plugin_NAME.so,
# placed beside the core library so that the host finds it.
function(airshape_add_plugin name)
  set(target airshape_plugin_${name})
  add_library(${target} MODULE ${ARGN})
  target_link_libraries(${target} PRIVATE airshape::core airshape_warnings TKTopAlgo TKGeomAlgo TKBO)
  set_target_properties(${target} PROPERTIES PREFIX "lib" LIBRARY_OUTPUT_DIRECTORY ${CMAKE_LIBRARY_OUTPUT_DIRECTORY})
  install(TARGETS ${target} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()

# airshape_select_plugins(OUT plugin...): the plugins asked for and, transitively, those they
# build on, as each plugin folder's manifest (plugins/NAME/plugin.cmake) names them in
# AIRSHAPE_PLUGIN_REQUIRES; required plugins come first. An unknown name is a fatal error.
# A plugin's public interface (its include/ folder, header-only): the target
# airshape::<name> for the plugins that build on it and use it through Plugin::useServices,
# exported to the build tree's airshape<Name>Targets.cmake and installed.
function(airshape_plugin_interface name)
  string(SUBSTRING ${name} 0 1 first)
  string(TOUPPER ${first} first)
  string(SUBSTRING ${name} 1 -1 rest)
  set(targets airshape${first}${rest}Targets)
  add_library(airshape_${name}_interface INTERFACE)
  add_library(airshape::${name} ALIAS airshape_${name}_interface)
  target_include_directories(airshape_${name}_interface INTERFACE
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(airshape_${name}_interface PROPERTIES EXPORT_NAME ${name})
  export(TARGETS airshape_${name}_interface NAMESPACE airshape:: FILE ${CMAKE_BINARY_DIR}/${targets}.cmake)
  install(TARGETS airshape_${name}_interface EXPORT ${targets})
  install(DIRECTORY include/airshape DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT ${targets} NAMESPACE airshape:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/airshape)
endfunction()

function(airshape_select_plugins out)
  set(selected)
  set(visiting)
  macro(airshape_visit_plugin plugin)
    if(NOT "${plugin}" IN_LIST AIRSHAPE_ALL_PLUGINS)
      message(FATAL_ERROR "AIRSHAPE_PLUGINS: unknown plugin '${plugin}' (known: ${AIRSHAPE_ALL_PLUGINS})")
    endif()
    if(NOT "${plugin}" IN_LIST selected AND NOT "${plugin}" IN_LIST visiting)
      list(APPEND visiting ${plugin})
      set(AIRSHAPE_PLUGIN_REQUIRES)
      include(${AIRSHAPE_PLUGIN_FOLDER}/${plugin}/plugin.cmake)
      set(requires_${plugin} ${AIRSHAPE_PLUGIN_REQUIRES})
      foreach(required IN LISTS requires_${plugin})
        airshape_visit_plugin(${required})
      endforeach()
      list(APPEND selected ${plugin})
    endif()
  endmacro()
  foreach(plugin IN LISTS ARGN)
    airshape_visit_plugin(${plugin})
  endforeach()
  set(${out} ${selected} PARENT_SCOPE)
endfunction()
