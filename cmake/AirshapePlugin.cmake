# airshape_add_plugin(NAME source...): a plugin module named libairshape_plugin_NAME.so,
# placed beside the core library so that the host finds it.
function(airshape_add_plugin name)
  set(target airshape_plugin_${name})
  add_library(${target} MODULE ${ARGN})
  target_link_libraries(${target} PRIVATE airshape::core airshape_warnings TKTopAlgo TKGeomAlgo TKBO)
  set_target_properties(${target} PROPERTIES PREFIX "lib" LIBRARY_OUTPUT_DIRECTORY ${CMAKE_LIBRARY_OUTPUT_DIRECTORY})
  install(TARGETS ${target} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()
