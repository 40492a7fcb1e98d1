# contensou_install_module(<component> <targets...>): installs a module's libraries and exports
# them as contensou-<component>-targets.cmake, a component of the package config.
function(contensou_install_module component)
  install(TARGETS ${ARGN} EXPORT contensou-${component}-targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT contensou-${component}-targets NAMESPACE contensou::
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/contensou)
endfunction()
